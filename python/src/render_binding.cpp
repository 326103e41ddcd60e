// raylab.render, raylab.progressive and raylab.debug_view: raylab-render's image and debug views,
// traced by the same tracer variants with the same settings, so the arrays equal its EXR files
// bit for bit for the same scene and seed.
#include "bindings.h"

#include "bench/error_metrics.h"
#include "render/debug_buffers.h"
#include "render/progressive_render.h"
#include "render/resume.h"
#include "render/scene_stats.h"
#include "scene/estimator_stages.h"
#include "scene/parameters.h"
#include "scene/scene_keys.h"


#include <optional>

namespace raylab::python {

namespace {

TracerEntry parseEntry(const std::string& name) {
    if (name == "fragment") return TracerEntry::Fragment;
    if (name == "compute") return TracerEntry::Compute;
    throw py::value_error("tracer: expected 'fragment' or 'compute', got '" + name + "'");
}

// The scene with the call's keyword arguments applied as raylab-render applies its flags.
Scene withSettings(const PyScene& s, std::optional<int> spp, std::optional<long long> seed, std::optional<double> time,
                   std::optional<int> rpp) {
    Scene scene = s.scene;
    if (spp) setParam(scene, "render.spp", std::to_string(*spp));
    if (seed) setParam(scene, "render.seed", std::to_string(*seed));
    if (time) setParam(scene, "render.time", formatNumber(*time));
    if (rpp) setParam(scene, "render.rpp", std::to_string(*rpp));
    return scene;
}

struct Rendered {
    Image image;
    nlohmann::json meta;
};

nlohmann::json metadata(const PathTracer& tracer, const Scene& scene, const RenderOutcome& outcome,
                        const std::string& entry, const GlState& gl) {
    nlohmann::json meta = {
        {"spp", tracer.samplesPerPixel()},
        {"seconds", outcome.last.elapsed},
        {"non_finite", tracer.nonFiniteSamples()},
        {"variant", tracer.variantName()},
        {"compile_seconds", tracer.compileSeconds()},
        {"sampler", formatValue(*findParameter("render.sampler"), std::int64_t(scene.render.sampler))},
        {"seed", scene.render.seed},
        {"rpp", scene.render.rpp},
        {"passes", tracer.passes()},
        {"rays", tracer.raysTraced()},
        {"loop_limited", tracer.loopLimitedInvocations()},
        {"width", tracer.width()},
        {"height", tracer.height()},
        {"tracer", entry},
        {"scene", scene.sourcePath.string()},
        {"settings_hash", settingsHash(scene)},
        {"gl", gl.context},
        {"interrupted", outcome.interrupted},
    };
    for (const auto& [name, value] : estimatorStages(scene)) meta[name] = value;
    return meta;
}

py::tuple result(Rendered r) {
    return py::make_tuple(toArray(r.image), toPython(r.meta));
}

py::tuple renderImage(const PyScene& s, std::optional<int> spp, std::optional<long long> seed,
                      std::optional<double> time, std::optional<int> rpp, const std::string& tracerName) {
    const TracerEntry entry = parseEntry(tracerName);
    const Scene scene = withSettings(s, spp, seed, time, rpp);
    std::atomic<bool> stop{false};
    return result(onGlThread(
        [&](GlState& gl) {
            PathTracer& tracer = gl.tracer(entry, TracerVariant::Beauty);
            tracer.setScene(scene);   // restarts accumulation
            const RenderOutcome outcome = renderProgressively(tracer, scene.render, &stop);
            return Rendered{tracer.readImage(), metadata(tracer, scene, outcome, tracerName, gl)};
        },
        &stop));
}

py::tuple debugView(const PyScene& s, const std::string& name, std::optional<int> spp, std::optional<long long> seed,
                    int bounce, const std::string& tracerName) {
    const std::optional<DebugView> view = parseDebugView(name);
    if (!view || !tracedDebugView(*view)) {
        std::string names;
        for (const DebugViewInfo& v : kDebugViewTable)
            if (v.traced) names += (names.empty() ? "" : ", ") + std::string(v.name);
        throw py::value_error("debug_view: unknown view '" + name + "'; the traced views are " + names);
    }
    if (bounce < 0) throw py::value_error("debug_view: bounce must be >= 0");
    const TracerEntry entry = parseEntry(tracerName);
    const Scene scene = withSettings(s, spp, seed, std::nullopt, std::nullopt);
    std::atomic<bool> stop{false};
    return result(onGlThread(
        [&](GlState& gl) {
            PathTracer& tracer = gl.tracer(entry, variantFor(*view));
            tracer.setScene(scene);
            setTracedView(tracer.program(), *view, bounce);
            std::optional<DebugBuffers> heat;   // the heat maps' largest count
            if (heatMapView(*view)) {
                heat.emplace();
                heat->restart(0, 0);
                heat->bind();
            }
            const RenderOutcome outcome = renderProgressively(tracer, scene.render, &stop);
            Rendered r{tracer.readImage(), metadata(tracer, scene, outcome, tracerName, gl)};
            r.meta["view"] = name;
            r.meta["legend"] = std::string(debugViewInfo(*view).legend);   // how the viewer reads the values
            if (heat) {
                const glm::uvec2 most = heat->heatMax();
                r.meta["box_tests_max"] = most.x;
                r.meta["triangle_tests_max"] = most.y;
            }
            return r;
        },
        &stop));
}

// raylab.progressive's state: one tracer of its own that keeps its samples between checkpoints.
class Progressive {
public:
    Progressive(const PyScene& s, std::vector<std::uint64_t> checkpoints, std::optional<long long> seed,
                std::optional<int> rpp, const std::string& tracerName)
        : entryName_(tracerName), checkpoints_(std::move(checkpoints)) {
        const TracerEntry entry = parseEntry(tracerName);
        if (checkpoints_.empty()) throw py::value_error("progressive: checkpoints is empty");
        for (std::size_t i = 0; i < checkpoints_.size(); ++i)
            if (checkpoints_[i] < 1 || (i > 0 && checkpoints_[i] <= checkpoints_[i - 1]))
                throw py::value_error("progressive: checkpoints must be increasing sample counts >= 1");
        // The last checkpoint is the render's spp: the stratified sampler lays its strata out for it.
        scene_ = withSettings(s, int(std::min<std::uint64_t>(checkpoints_.back(), std::uint64_t(INT32_MAX))), seed,
                              std::nullopt, rpp);
        tracer_ = onGlThread([entry, this](GlState&) {
            auto tracer = std::make_unique<PathTracer>(variantOptions(TracerVariant::Beauty, entry));
            tracer->setScene(scene_);
            return tracer;
        });
    }
    ~Progressive() {
        // GL objects go on the GL thread; after shutdown (the interpreter exiting) the process ends anyway.
        if (GlWorker* worker = GlWorker::running(); worker && tracer_)
            worker->post([t = std::shared_ptr<PathTracer>(std::move(tracer_))](GlState&) mutable { t.reset(); });
        else
            (void)tracer_.release();
    }
    Progressive(const Progressive&) = delete;
    Progressive& operator=(const Progressive&) = delete;

    py::tuple next() {
        if (next_ >= checkpoints_.size()) throw py::stop_iteration();
        const std::uint64_t target = checkpoints_[next_++];
        std::atomic<bool> stop{false};
        return result(onGlThread(
            [&](GlState& gl) {
                RenderSettings settings = scene_.render;
                settings.spp = int(target);
                settings.timeBudget = 0.0;
                const RenderOutcome outcome = renderProgressively(*tracer_, settings, &stop);
                seconds_ += outcome.last.elapsed;
                Rendered r{tracer_->readImage(), metadata(*tracer_, scene_, outcome, entryName_, gl)};
                r.meta["seconds"] = seconds_;   // since the first sample
                return r;
            },
            &stop));
    }

private:
    std::string entryName_;
    std::vector<std::uint64_t> checkpoints_;
    std::size_t next_ = 0;
    Scene scene_;
    std::unique_ptr<PathTracer> tracer_;
    double seconds_ = 0.0;
};

} // namespace

void bindRender(py::module_& m) {
    m.def("_render", &renderImage, py::arg("scene"), py::arg("spp") = py::none(), py::arg("seed") = py::none(),
          py::arg("time") = py::none(), py::arg("rpp") = py::none(), py::arg("tracer") = "fragment");
    m.def("_debug_view", &debugView, py::arg("scene"), py::arg("view"), py::arg("spp") = py::none(),
          py::arg("seed") = py::none(), py::arg("bounce") = 1, py::arg("tracer") = "fragment");
    m.def("debug_views", [] {
        std::vector<std::string> names;
        for (const DebugViewInfo& v : kDebugViewTable)
            if (v.traced) names.emplace_back(v.name);
        return names;
    }, "The names debug_view takes (the views raylab-render --debug-view traces).");
    m.def("gl_info", [] { return onGlThread([](GlState& gl) { return gl.context; }); },
          "The OpenGL context the module renders with: backend, renderer and version.");
    py::class_<Progressive>(m, "_Progressive")
        .def(py::init<const PyScene&, std::vector<std::uint64_t>, std::optional<long long>, std::optional<int>,
                      const std::string&>(),
             py::arg("scene"), py::arg("checkpoints"), py::arg("seed") = py::none(), py::arg("rpp") = py::none(),
             py::arg("tracer") = "fragment")
        .def("next", &Progressive::next);
}

} // namespace raylab::python
