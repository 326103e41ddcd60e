// raylab.Scene: a validated scene, read and edited through the keys of scenes/FORMAT.md with the
// resolver and checks of raylab-render's --set and the viewer's panels (scene/scene_keys.h).
#include "bindings.h"

#include "scene/scene_keys.h"
#include "scene/scene_loader.h"
#include "scene/scene_save.h"
#include "scene/scene_writer.h"


#include <sstream>

namespace raylab::python {

namespace {

// {"render.spp": 64} or ["render.spp=64"] -> the loader's "KEY=VALUE" overrides (values as JSON).
std::vector<std::string> overridesFrom(const py::object& set) {
    std::vector<std::string> out;
    if (set.is_none()) return out;
    if (py::isinstance<py::dict>(set)) {
        for (const auto& [k, v] : set.cast<py::dict>()) {
            const nlohmann::json value = fromPython(v);
            out.push_back(py::str(k).cast<std::string>() + "=" +
                          (value.is_string() ? value.get<std::string>() : value.dump()));
        }
        return out;
    }
    for (const auto& item : set.cast<py::sequence>()) out.push_back(py::str(item).cast<std::string>());
    return out;
}

bool isIndex(const std::string& s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos && s.size() < 10;
}

// A file or name key (a texture, sky.map, a mesh's file, an object's material) as the scene would
// be saved beside its own file: the text the user wrote.
py::object writtenValue(const Scene& scene, const std::string& key) {
    nlohmann::json node = sceneToJson(scene);
    for (const std::string& part : splitKey(key)) {
        if (node.is_object() && node.contains(part)) {
            node = node[part];
        } else if (isIndex(part) && (node.is_array() || node.is_object()) && std::stoul(part) < node.size()) {
            node = node.is_array() ? node[std::stoul(part)] : std::next(node.begin(), long(std::stoul(part))).value();
        } else {
            return py::none();   // resolveParam accepted it: a key the file leaves out (an absent texture)
        }
    }
    return toPython(node);
}

py::object getKey(const PyScene& s, const std::string& key) {
    const SceneParam param = resolveParam(s.scene, key);   // EditError: unknown key, with a suggestion
    if (param.spec && param.get) return paramToPython(*param.spec, param.get(s.scene));
    return writtenValue(s.scene, key);
}

void setKey(PyScene& s, const std::string& key, const py::object& value) {
    const nlohmann::json json = fromPython(value);
    try {
        setParam(s.scene, key, json.is_string() ? json.get<std::string>() : json.dump());
    } catch (const EditError& e) {
        // Material and object keys' messages name the item's own key; say which item.
        const std::string what = e.what();
        if (what.rfind(key, 0) == 0) throw;
        throw EditError(key + ": " + what.substr(what.find(": ") == std::string::npos ? 0 : what.find(": ") + 2));
    }
}

PyScene loadFile(const std::string& path, const py::object& set) {
    const std::vector<std::string> overrides = overridesFrom(set);
    py::gil_scoped_release released;   // meshes and images may take a while
    return PyScene{loadScene(path, overrides)};
}

PyScene parseText(const std::string& text, const std::string& name, const py::object& set) {
    return PyScene{parseScene(text, name, overridesFrom(set))};
}

std::string describe(const PyScene& s) {
    std::ostringstream out;
    out << "<raylab.Scene '" << s.scene.sourcePath.string() << "' " << s.scene.render.width << "x"
        << s.scene.render.height << ", " << s.scene.spheres.size() << " spheres, " << s.scene.meshes.size()
        << " meshes, " << s.scene.materials.size() << " materials>";
    return out.str();
}

} // namespace

void bindScene(py::module_& m) {
    py::class_<PyScene>(m, "Scene",
                        "A validated scene. Read and set any key of scenes/FORMAT.md by its dotted name, as "
                        "raylab-render's --set takes it: scene['materials.red.roughness'] = 0.3. A value the "
                        "scene refuses raises SceneError and leaves the scene as it was.")
        .def("__getitem__", &getKey, py::arg("key"),
             "The value of a key: a number, a bool, an enum's name, an (x, y, z) tuple, or a file or name as "
             "written (None when the scene has none).")
        .def("__setitem__", &setKey, py::arg("key"), py::arg("value"),
             "Sets a key after the loader's checks; raises SceneError naming the key and what is wrong.")
        .def("__contains__",
             [](const PyScene& s, const std::string& key) {
                 try {
                     resolveParam(s.scene, key);
                     return true;
                 } catch (const EditError&) {
                     return false;
                 }
             })
        .def("keys", [](const PyScene& s) { return sceneKeys(s.scene); }, "Every key of this scene, in file order.")
        .def("__iter__", [](const PyScene& s) { return py::iter(py::cast(sceneKeys(s.scene))); })
        .def("__len__", [](const PyScene& s) { return sceneKeys(s.scene).size(); })
        .def("to_json", [](const PyScene& s) { return toPython(sceneToJson(s.scene)); },
             "The scene in the file format, as a dict (paths relative to the scene's own file).")
        .def("save", [](const PyScene& s, const std::string& path) { saveSceneFile(s.scene, path); }, py::arg("path"),
             "Writes the scene file atomically, paths relative to the new file (as the viewer's Ctrl-S).")
        .def("copy", [](const PyScene& s) { return PyScene{s.scene}; }, "An independent copy.")
        .def("__copy__", [](const PyScene& s) { return PyScene{s.scene}; })
        .def("__deepcopy__", [](const PyScene& s, const py::dict&) { return PyScene{s.scene}; }, py::arg("memo"))
        .def_property_readonly("path", [](const PyScene& s) { return s.scene.sourcePath.string(); },
                               "The file the scene was read from.")
        .def_property_readonly("warnings", [](const PyScene& s) { return s.scene.warnings; },
                               "What the loader warned about (as raylab-render prints them).")
        .def_property_readonly("size", [](const PyScene& s) { return py::make_tuple(s.scene.render.width, s.scene.render.height); },
                               "(width, height) in pixels.")
        .def("__repr__", &describe);

    m.def("load", &loadFile, py::arg("path"), py::arg("set") = py::none(),
          "Reads, parses and validates a scene file. `set` overrides keys before validation, as "
          "raylab-render's --set: {'render.spp': 64, 'materials.red.albedo': [1, 0, 0]}. Raises SceneError "
          "with the file, line, column and key's path of the first mistake.");
    m.def("parse", &parseText, py::arg("text"), py::arg("name") = "<string>", py::arg("set") = py::none(),
          "A scene from JSON text in memory; `name` is used in messages and relative paths resolve "
          "from the working directory.");
}

} // namespace raylab::python
