#pragma once
// `raylab-bench scaling`: how the cost of a pass grows with the scene and the image: ms per
// sample per pixel against sphere count (random spheres over a ground) and against resolution,
// plus startup (scene upload, shader compile, first pass). Writes scaling.csv and scaling.md.
// Needs a current GL context.
#include <filesystem>
#include <string>

namespace raylab {

struct ScalingOptions {
    std::filesystem::path outputDir = "bench/results";
    int spp = 8;        // samples per pixel per measurement (after one warm-up pass)
    int repeat = 3;     // median of this many
    std::string commandLine;
};

int runScaling(const ScalingOptions& options);

} // namespace raylab
