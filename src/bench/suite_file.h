#pragma once
// The suite file of `raylab-bench convergence` (bench/suite.json): its modes and scenes, read with
// the scene format's error wording, so a mistake names FILE:LINE:COL and the key's path
// ("suite.json:24:20: error: modes.quick.seeds: expected an integer, got string").
#include <glm/vec3.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

struct SuiteMode {
    int width = 96, height = 54, maxSpp = 512, seeds = 1, referenceSpp = 4096, referenceBatches = 4,
        peerMaxSpp = 64;
    // Cycles' reference needs only to be long against Cycles' own curve (peerMaxSpp), and Cycles
    // costs several times raylab per sample here: "peer_reference_spp" (default: reference_spp).
    int peerReferenceSpp = 4096;
    // Blender runs per Cycles point; the point's time is their median. One run's time jitters by
    // up to ±0.5 s here (measured: 1.5 s for 1 spp, 0.65 s for 2 spp), so a fair comparison wants
    // three; a quick look can take one. "peer_timing_runs" (default 1).
    int peerTimingRuns = 1;
    // Cycles' curve goes on past peerMaxSpp, doubling up to this, only while a goal level that
    // raylab reached is not reached by Cycles (the goal would get a bound there, not a ratio).
    // "peer_extend_spp" (default: peer_max_spp, no extension).
    int peerExtendSpp = 64;
    // Past peerExtendSpp the curve goes on doubling up to this only while its longest run is still
    // under the goal's ratio times raylab's time at a level it has not reached: the bound it then
    // gives decides the goal, without the samples a ratio would take. "peer_decide_spp" (default:
    // peer_extend_spp).
    int peerDecideSpp = 64;
    // raylab's curves of a peer scene (every seed, not the variants) are rendered again up to this
    // when their mean misses a goal level at maxSpp (curveMissesALevel), so that level is decided
    // where more samples can decide it. "extend_spp" (default: max_spp, no extension).
    int extendSpp = 512;
    // A second Cycles curve, "cycles:adaptive": one run per noise threshold, with adaptive
    // sampling on and Blender's starting 4096 samples at most, as a user turning the threshold
    // gets them (bench/adaptive_sampling.md); the goal then takes the faster curve at each level.
    // Decreasing; the runs stop once they reach every goal level raylab reached.
    // "peer_thresholds" (default none: no second curve).
    std::vector<double> peerThresholds;
};

struct SuiteScene {
    std::string name;
    std::filesystem::path scene;
    bool analytic = false;
    glm::vec3 analyticValue{0.0f};
    bool peer = false;
    // Extra raylab curves of the same scene against the same reference, each a list of --set
    // overrides (e.g. NEE off / NEE without MIS / MIS): efficiency of estimators at equal time.
    std::vector<std::pair<std::string, std::vector<std::string>>> variants;
};

struct Suite {
    SuiteMode mode;
    std::vector<SuiteScene> scenes;   // in the file's order
};

// A suite file that cannot be read or is wrong; what() is the whole located message.
class SuiteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads `file`, takes the mode named `mode` and every scene (all of them; the caller picks).
// Unknown keys are refused with the closest known one suggested, like the scene format's.
Suite readSuite(const std::filesystem::path& file, const std::string& mode);

} // namespace raylab
