#pragma once
// Runs passes until the target samples per pixel or the time budget is reached, or until asked
// to stop; reports progress after every pass. Used by raylab-render, raylab-bench and tests.
#include "render/path_tracer.h"

#include <atomic>
#include <cstdint>
#include <functional>

namespace raylab {

struct RenderProgress {
    std::uint64_t spp = 0;         // samples per pixel accumulated
    std::uint64_t targetSpp = 0;
    double elapsed = 0.0;          // seconds, tracing only
    double eta = 0.0;              // seconds left at the current speed (by spp or time budget)
    double mpathsPerSecond = 0.0;  // camera paths (samples) per second, millions
    double mraysPerSecond = 0.0;   // ray casts per second, millions
    std::uint64_t nonFinite = 0;
};

struct RenderOutcome {
    RenderProgress last;
    bool interrupted = false;      // stopped by the stop flag before reaching the target
};

// Passes of settings.rpp samples (the last one shortened to land exactly on settings.spp), from
// the samples the tracer holds (0, or those of a resumed render: PathTracer::restoreAccumulation).
// settings.timeBudget > 0 also stops after that many seconds (after the pass that crosses it).
RenderOutcome renderProgressively(PathTracer& tracer, const RenderSettings& settings,
                                  const std::atomic<bool>* stop = nullptr,
                                  const std::function<void(const RenderProgress&)>& onPass = {});

} // namespace raylab
