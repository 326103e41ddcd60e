// Images and error metrics for notebooks: raylab's own EXR/PNG reader and writer (io/image_io.h),
// the benchmark's error metrics (bench/error_metrics.h) and its references (bench/reference.h),
// and the Blender export (bench/blender_export.h).
#include "bindings.h"

#include "bench/blender_export.h"
#include "bench/error_metrics.h"
#include "bench/reference.h"
#include "io/image_io.h"
#include "render/path_tracer.h"
#include "scene/parameters.h"
#include "scene/scene_writer.h"

#include <optional>

namespace raylab::python {

namespace {

nlohmann::json metadataJson(const RenderMetadata& m) {
    nlohmann::json meta = {{"spp", m.spp},           {"seconds", m.renderSeconds}, {"seed", m.seed},
            {"scene", m.sceneFile},   {"non_finite", m.nonFiniteSamples}, {"sampler", m.sampler},
            {"target_spp", m.targetSpp}, {"rpp", m.rpp},             {"passes", m.passes},
            {"tracer", m.tracer},     {"settings_hash", m.settingsHash}, {"version", m.version}};
    for (const auto& [name, value] : m.stages) meta[name] = value;
    return meta;
}

py::tuple readImageFile(const std::string& path) {
    Image image;
    nlohmann::json meta = nlohmann::json::object();
    {
        py::gil_scoped_release released;
        image = readImage(path);
        if (imageFormatFor(path) == ImageFormat::Exr) {
            try {
                meta = metadataJson(readRenderMetadata(path));
            } catch (const std::exception&) {
                // an EXR that raylab did not write has no render metadata
            }
        }
    }
    return py::make_tuple(toArray(image), toPython(meta));
}

void writeImageFile(const py::object& array, const std::string& path, double exposure, const std::string& toneMap) {
    const ValueSpec& spec = *findParameter("render.tone_map");
    const EnumName* op = spec.findEnum(toneMap);
    if (!op) throw py::value_error("tone_map: expected one of clamp, reinhard, aces; got '" + toneMap + "'");
    const Image image = fromArray(array, "write_image");
    py::gil_scoped_release released;
    writeImage(path, image, RenderMetadata{}, DisplayTransform{float(exposure), ToneMap(op->value)});
}

py::dict errorOf(const py::object& image, const py::object& reference) {
    const ImageError e = imageError(fromArray(image, "image"), fromArray(reference, "reference"));
    py::dict out;
    out["mse"] = e.mse;
    out["rmse"] = e.rmse;
    out["relmse"] = e.relMse;
    return out;
}

// raylab-bench's reference of a scene (renderReferenceBatch), cached in `cache` (a path without
// extension) when given.
py::tuple reference(const PyScene& s, int spp, int batches, const std::optional<std::string>& cache) {
    if (spp < 1) throw py::value_error("spp must be at least 1");
    if (batches < 2) throw py::value_error("batches must be at least 2 (the variance of the mean needs two)");
    const Scene scene = s.scene;
    std::atomic<bool> stop{false};
    auto renderBatch = [&](int k) {
        return onGlThread([&](GlState& gl) {
            return renderReferenceBatch(gl.tracer(TracerEntry::Fragment, TracerVariant::Beauty), scene, k, spp, &stop);
        }, &stop);
    };
    const std::string description = "mean of " + std::to_string(batches) + " raylab renders × " + std::to_string(spp) + " spp";
    Reference r;
    if (cache) {
        const std::string key = "raylab " RAYLAB_VERSION " python " + textHash(sceneToJson(scene).dump()) + " " +
                                std::to_string(scene.render.width) + "x" + std::to_string(scene.render.height) + " " +
                                std::to_string(spp) + "x" + std::to_string(batches);
        r = cachedReference(*cache, key, batches, renderBatch, description, "raylab.reference");
    } else {
        r = batchReference(batches, renderBatch, description, "raylab.reference");
    }
    py::dict meta;
    meta["description"] = r.description;
    meta["from_cache"] = r.fromCache;
    meta["seconds"] = r.seconds;
    return py::make_tuple(toArray(r.mean), toArray(r.variance), meta);
}

} // namespace

void bindImages(py::module_& m) {
    m.def("_read_image", &readImageFile, py::arg("path"));
    m.def("write_image", &writeImageFile, py::arg("image"), py::arg("path"), py::arg("exposure") = 0.0,
          py::arg("tone_map") = "aces",
          "Writes (H, W, 3 or 4) linear values as .exr (linear float) or .png (exposure, tone map and sRGB "
          "applied, as raylab-render writes them).");
    m.def("error", &errorOf, py::arg("image"), py::arg("reference"),
          "The benchmark's errors over the RGB channels of every pixel: mse, rmse and relmse (the relative "
          "MSE of Rousselle, Knaus & Zwicker 2011).");
    m.def("rmse", [](const py::object& a, const py::object& b) {
        return imageError(fromArray(a, "image"), fromArray(b, "reference")).rmse;
    }, py::arg("image"), py::arg("reference"), "Root mean squared error over the RGB channels of every pixel.");
    m.def("mean", [](const py::object& a) { return imageMean(fromArray(a, "image")); }, py::arg("image"),
          "Mean of the RGB channels over all pixels.");
    m.def("_reference", &reference, py::arg("scene"), py::arg("spp") = 1024, py::arg("batches") = 4,
          py::arg("cache") = py::none());
    m.def("export_blender", [](const PyScene& s, const std::string& path) { writeBlenderScript(s.scene, path); },
          py::arg("scene"), py::arg("path"),
          "Writes a Blender 3.4 script that rebuilds the scene for Cycles (raylab-render --export-blender).");
}

} // namespace raylab::python
