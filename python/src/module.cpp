// raylab._raylab: the C++ half of the Python package raylab (python/raylab/__init__.py is the
// other half). The renderer's own code runs here; nothing is re-implemented.
#include "bindings.h"

#include "gl/shader_source.h"
#include "scene/scene_error.h"
#include "scene/scene_keys.h"

namespace raylab::python {

namespace {
py::object g_sceneError;
py::object g_renderError;
} // namespace

py::object sceneErrorType() { return g_sceneError; }
py::object renderErrorType() { return g_renderError; }

py::array_t<float> toArray(const Image& image) {
    py::array_t<float> out({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(4)});
    std::copy(image.rgba.begin(), image.rgba.end(), out.mutable_data());
    return out;
}

Image fromArray(const py::object& array, const char* what) {
    const auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
    if (!a || a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4) || a.shape(0) < 1 || a.shape(1) < 1)
        throw py::value_error(std::string(what) + ": expected a float array of shape (height, width, 3 or 4)");
    Image image(int(a.shape(1)), int(a.shape(0)));
    const int channels = int(a.shape(2));
    const float* src = a.data();
    for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p)
        for (int c = 0; c < 4; ++c) image.rgba[p * 4 + c] = c < channels ? src[p * channels + c] : 1.0f;
    return image;
}

py::object paramToPython(const ValueSpec& spec, const ParamValue& value) {
    switch (spec.type) {
    case ParamType::Bool: return py::bool_(std::get<std::int64_t>(value) != 0);
    case ParamType::Enum: return py::str(std::string(spec.enumName(std::get<std::int64_t>(value))));
    case ParamType::Int:
    case ParamType::UInt: return py::int_(std::get<std::int64_t>(value));
    case ParamType::Float: return py::float_(std::get<double>(value));
    case ParamType::Vec3:
    case ParamType::Rgb: {
        const glm::vec3 v = std::get<glm::vec3>(value);
        return py::make_tuple(double(v.x), double(v.y), double(v.z));
    }
    }
    return py::none();
}

py::object toPython(const nlohmann::json& value) {
    switch (value.type()) {
    case nlohmann::json::value_t::null: return py::none();
    case nlohmann::json::value_t::boolean: return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(value.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(value.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(value.get<double>());
    case nlohmann::json::value_t::string: return py::str(value.get<std::string>());
    case nlohmann::json::value_t::array: {
        py::list list;
        for (const auto& v : value) list.append(toPython(v));
        return list;
    }
    case nlohmann::json::value_t::object: {
        py::dict dict;
        for (const auto& [k, v] : value.items()) dict[py::str(k)] = toPython(v);
        return dict;
    }
    default: return py::none();
    }
}

nlohmann::json fromPython(const py::handle& value) {
    if (value.is_none()) return nullptr;
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
    if (py::isinstance<py::int_>(value)) return value.cast<std::int64_t>();
    if (py::isinstance<py::float_>(value)) return value.cast<double>();
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::dict>(value)) {
        nlohmann::json object = nlohmann::json::object();
        for (const auto& [k, v] : value.cast<py::dict>()) object[py::str(k).cast<std::string>()] = fromPython(v);
        return object;
    }
    // numpy scalars and arrays, tuples, lists
    if (py::hasattr(value, "tolist") && !py::isinstance<py::list>(value)) return fromPython(value.attr("tolist")());
    if (py::isinstance<py::sequence>(value)) {
        nlohmann::json array = nlohmann::json::array();
        for (const auto& v : value.cast<py::sequence>()) array.push_back(fromPython(v));
        return array;
    }
    throw py::type_error("raylab: cannot use a value of type " + py::str(value.get_type().attr("__name__")).cast<std::string>() +
                         " in a scene (numbers, strings, booleans and lists of them)");
}

} // namespace raylab::python

using namespace raylab::python;

PYBIND11_MODULE(_raylab, m) {
    m.doc() = "raylab's renderer, scenes, path inspector and GLSL samplers (see the raylab package)";
    g_sceneError = py::reinterpret_borrow<py::object>(
        PyErr_NewExceptionWithDoc("raylab.SceneError",
                                  "A located mistake in a scene file, a --set style key or value, a mesh or an image: "
                                  "the message is raylab-render's (file:line:col, the key's path, what is wrong).",
                                  PyExc_ValueError, nullptr));
    g_renderError = py::reinterpret_borrow<py::object>(
        PyErr_NewExceptionWithDoc("raylab.RenderError",
                                  "No usable OpenGL 4.5 context, or a shader that did not compile or link.",
                                  PyExc_RuntimeError, nullptr));
    m.attr("SceneError") = g_sceneError;
    m.attr("RenderError") = g_renderError;
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const raylab::SceneError& e) {
            PyErr_SetString(g_sceneError.ptr(), e.what());
        } catch (const raylab::EditError& e) {
            PyErr_SetString(g_sceneError.ptr(), e.what());
        } catch (const raylab::ShaderError& e) {
            PyErr_SetString(g_renderError.ptr(), e.what());
        }
    });
    m.def("_shutdown", &GlWorker::shutdown,
          "Stops the GL thread and destroys its context (registered with atexit by the package).");
    bindScene(m);
    bindRender(m);
    bindInspect(m);
    bindBsdf(m);
    bindImages(m);
}
