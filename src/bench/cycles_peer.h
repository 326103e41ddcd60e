#pragma once
// Runs Blender's Cycles on a script written by blender_export.h and reads its image back.
// Benchmarks only: Blender is never needed to build or test raylab.
#include "render/image.h"

#include <filesystem>
#include <string>

namespace raylab {

struct CyclesRun {
    Image image;
    double seconds = 0.0;   // the render call alone, as Blender timed it
};

// True when `blender` is on PATH and runs; otherwise false with the reason.
bool blenderAvailable(std::string* why);

// Throws std::runtime_error with Blender's output tail when the run fails. An `adaptiveThreshold`
// of 0 or more turns on Cycles' adaptive sampling (on as Blender starts) at that noise threshold,
// `samples` then being the most a pixel takes (0: Cycles sets the threshold from `samples`).
CyclesRun runCycles(const std::filesystem::path& script, int samples, int threads, int seed,
                    const std::filesystem::path& workDir, double adaptiveThreshold = -1.0);

} // namespace raylab
