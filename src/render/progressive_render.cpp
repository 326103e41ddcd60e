#include "render/progressive_render.h"

#include <algorithm>
#include <chrono>

namespace raylab {

RenderOutcome renderProgressively(PathTracer& tracer, const RenderSettings& settings,
                                  const std::atomic<bool>* stop,
                                  const std::function<void(const RenderProgress&)>& onPass) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const std::uint64_t target = std::uint64_t(settings.spp);
    const std::uint64_t startSpp = tracer.samplesPerPixel();   // above 0 for a resumed render
    RenderOutcome out;
    out.last.targetSpp = target;
    out.last.spp = startSpp;
    while (tracer.samplesPerPixel() < target) {
        if (stop && stop->load()) {
            out.interrupted = true;
            break;
        }
        const std::uint64_t left = target - tracer.samplesPerPixel();
        tracer.renderPass(int(std::min<std::uint64_t>(left, std::uint64_t(settings.rpp))));

        RenderProgress& p = out.last;
        p.spp = tracer.samplesPerPixel();
        p.elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        p.nonFinite = tracer.nonFiniteSamples();
        if (p.elapsed > 0.0) {
            p.mpathsPerSecond = double(tracer.pathsTraced()) / p.elapsed * 1e-6;
            p.mraysPerSecond = double(tracer.raysTraced()) / p.elapsed * 1e-6;
        }
        const double bySpp = p.elapsed / double(p.spp - startSpp) * double(target - p.spp);
        p.eta = settings.timeBudget > 0.0 ? std::min(bySpp, std::max(0.0, settings.timeBudget - p.elapsed))
                                          : bySpp;
        if (onPass) onPass(p);
        if (settings.timeBudget > 0.0 && p.elapsed >= settings.timeBudget) break;
    }
    return out;
}

} // namespace raylab
