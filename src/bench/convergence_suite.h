#pragma once
// `raylab-bench convergence`: the run-time-against-error benchmark over the scenes of a suite
// file (bench/suite.json), against references, optionally side by side with Blender's Cycles.
// Writes convergence.csv, summary.md and gnuplot PNGs into the output directory.
#include <filesystem>
#include <string>

namespace raylab {

struct ConvergenceOptions {
    std::filesystem::path suiteFile = "bench/suite.json";
    std::string mode = "quick";                                  // a key of "modes"
    std::filesystem::path outputDir = "bench/results";           // + "/<mode>"
    std::filesystem::path referenceDir = "bench/references";
    std::string peer = "auto";                                   // auto | on | off
    std::string only;                                            // run just this scene name
    bool mainCurvesOnly = false;                                 // leave the scenes' variants out
    int threads = 2;                                             // Cycles threads (match llvmpipe's)
    std::string commandLine;                                     // recorded in the summary
    std::string glDescription;                                   // the GL renderer, recorded too
};

// Returns a process exit status (0 done, 1 bad input, 3 runtime failure); prints progress on stderr.
int runConvergenceSuite(const ConvergenceOptions& options);

} // namespace raylab
