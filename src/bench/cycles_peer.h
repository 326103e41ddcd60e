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

// Throws std::runtime_error with Blender's output tail when the run fails. `adaptive` turns on
// Cycles' adaptive sampling (on as Blender starts) with its threshold set from `samples`.
CyclesRun runCycles(const std::filesystem::path& script, int samples, int threads, int seed,
                    const std::filesystem::path& workDir, bool adaptive = false);

} // namespace raylab
