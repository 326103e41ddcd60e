#pragma once
// Pieces the binding files share: the Python exception types, waiting for the GL thread with the
// GIL released, and conversions between raylab's values and Python's.
#include "gl_worker.h"
#include "render/image.h"
#include "scene/parameters.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>   // in every binding file: pybind11 asks for one set of casters per type

#include <atomic>
#include <chrono>
#include <future>
#include <string>

namespace raylab::python {

namespace py = pybind11;

// The Python objects of raylab.SceneError (a ValueError: a located mistake in a scene, a key, a
// mesh or an image) and raylab.RenderError (a RuntimeError: no OpenGL 4.5, a shader failure).
py::object sceneErrorType();
py::object renderErrorType();

// A Scene as Python holds it: the validated scene, edited in place through scene keys.
struct PyScene {
    Scene scene;
};

// Waits for a GL job without the GIL, so that other Python threads run meanwhile. Ctrl-C (a
// pending KeyboardInterrupt) sets *stop, if given, waits for the job to wind down and raises.
template <class T>
T awaitJob(std::future<T> future, std::atomic<bool>* stop = nullptr) {
    bool interrupted = false;
    {
        py::gil_scoped_release released;
        while (future.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
            if (interrupted) continue;
            py::gil_scoped_acquire held;
            if (PyErr_CheckSignals() != 0) {
                interrupted = true;
                if (stop) stop->store(true);
            }
        }
    }
    if (interrupted) {
        try {
            future.get();
        } catch (...) {
        }
        throw py::error_already_set();
    }
    return future.get();
}

// Runs job(GlState&) on the GL thread and waits for it (awaitJob).
template <class F>
auto onGlThread(F job, std::atomic<bool>* stop = nullptr) {
    return awaitJob(GlWorker::instance().post(std::move(job)), stop);
}

// float32 (height, width, 4), top row first, a copy of the image.
py::array_t<float> toArray(const Image& image);
// An (H, W, 3) or (H, W, 4) float array as an Image (alpha 1 when absent); throws ValueError.
Image fromArray(const py::object& array, const char* what);

// A value of the parameter tables as Python: bool, int, an enum's name, float or an (x, y, z) tuple.
py::object paramToPython(const ValueSpec& spec, const ParamValue& value);

// JSON <-> Python, for metadata, path records and values of scene keys.
py::object toPython(const nlohmann::json& value);
nlohmann::json fromPython(const py::handle& value);

// The binding files' parts of the module.
void bindScene(py::module_& m);
void bindRender(py::module_& m);
void bindInspect(py::module_& m);
void bindBsdf(py::module_& m);
void bindImages(py::module_& m);

} // namespace raylab::python
