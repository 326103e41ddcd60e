// raylab.inspect: the path inspector's records of one pixel (inspect/path_inspector.h), every term
// of the estimator per bounce, in the form raylab-render --inspect writes to JSON.
#include "bindings.h"

#include "inspect/path_export.h"
#include "inspect/path_inspector.h"

namespace raylab::python {

namespace {

py::object inspect(const PyScene& s, int x, int y, int paths, std::uint64_t firstSample) {
    if (paths < 1 || paths > 4096) throw py::value_error("paths must be in [1, 4096]");
    const Scene& scene = s.scene;
    if (x < 0 || y < 0 || x >= scene.render.width || y >= scene.render.height)
        throw py::index_error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                              std::to_string(scene.render.width) + "x" + std::to_string(scene.render.height) + " image");
    const nlohmann::json records = onGlThread([&](GlState& gl) {
        PathInspector& inspector = gl.inspector();
        inspector.setScene(scene);
        return pathsToJson(inspector.record(x, y, paths, firstSample));
    });
    return toPython(records);
}

} // namespace

void bindInspect(py::module_& m) {
    m.def("inspect", &inspect, py::arg("scene"), py::arg("x"), py::arg("y"), py::arg("paths") = 4,
          py::arg("first_sample") = 0,
          "Records samples [first_sample, first_sample + paths) of image pixel (x, y) (top-left origin) as "
          "raylab-render --inspect does: the export's document as dicts and lists, every bounce with every "
          "term of the estimator (throughput, emission and its MIS weight, the light sample, the BSDF sample, "
          "Russian roulette).");
}

} // namespace raylab::python
