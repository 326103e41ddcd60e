#pragma once
// Run time against error: one progressive render read back at checkpoints (1, 2, 4, … spp), each
// compared with a reference. Time counts tracing only (readback and comparison excluded).
#include "bench/error_metrics.h"
#include "render/path_tracer.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace raylab {

struct Checkpoint {
    std::uint64_t spp = 0;
    double seconds = 0.0;   // tracing time up to this checkpoint
    ImageError error;
};

// Checkpoints at powers of two up to maxSpp (and maxSpp itself). The tracer must hold the scene.
std::vector<Checkpoint> runConvergence(PathTracer& tracer, int rpp, std::uint64_t maxSpp,
                                       const Image& reference);

// Least seconds at which the RMSE is at most target: the first crossing interpolated log–log
// between checkpoints, or a later checkpoint that took less time (separate runs, as a peer's,
// need not take longer for more samples); negative when the curve never gets there.
double timeToReach(const std::vector<Checkpoint>& curve, double targetRmse);

// 1 / (MSE × seconds) at a checkpoint (Veach; pbrt 3rd ed. §13.7): higher is better.
double efficiency(const Checkpoint& c);

// Least-squares slope of log RMSE against log spp (−0.5 for an unbiased estimator).
double convergenceSlope(const std::vector<Checkpoint>& curve);

// Several seeds' curves of one renderer as one: at each checkpoint the mean of their MSEs, RMSE its
// root, and the mean of their times, since the expected MSE is what a convergence rate and a time
// to error describe (bench/samplers.md). Throws std::invalid_argument when the checkpoints differ.
std::vector<Checkpoint> meanOverSeeds(std::span<const std::vector<Checkpoint>> curves);

// The time-to-error goal at one error level: raylab's time to reach it, its start-up included, is
// at most 1/goal of the peer's whole run (issue 13). Both curves reach the level: the ratio is
// measured. One does not: its time lies past its last checkpoint, so the ratio is a bound, and
// the goal is decided only when that bound settles it.
struct TimeToErrorGoal {
    enum class Verdict { Met, NotMet, Open };
    enum class Bound { Exact, AtLeast, AtMost, None };
    Verdict verdict = Verdict::Open;
    Bound bound = Bound::None;
    double ratio = 0.0;            // peer / raylab, or the bound (0 when neither reaches)
    double raylabSeconds = -1.0;   // start-up included; -1 when not reached
    double peerSeconds = -1.0;     // -1 when not reached
};

TimeToErrorGoal timeToErrorGoal(const std::vector<Checkpoint>& raylab, double raylabStartup,
                                const std::vector<Checkpoint>& peer, double raylabTarget, double peerTarget,
                                double goal);

// The goal against the fastest of several curves of one peer (Cycles with and without adaptive
// sampling): the one with the least time to the level, a curve that misses it counting its
// longest run's time (a lower bound), so the ratio is never flattered. `which` gets its index.
TimeToErrorGoal timeToErrorGoalAgainstFastest(const std::vector<Checkpoint>& raylab, double raylabStartup,
                                              std::span<const std::vector<Checkpoint>> peers, double raylabTarget,
                                              double peerTarget, double goal, size_t* which = nullptr);

// Whether a peer's curve should go on past its planned last point: at some goal level raylab's
// curve reached, the peer's has not, and the peer's longest run is still shorter than `goal` times
// raylab's time there (start-up included), so the bound it gives does not decide the goal.
bool peerCurveUndecided(const std::vector<Checkpoint>& raylab, const std::vector<Checkpoint>& peer,
                        std::span<const double> levels, double raylabMean, double peerMean,
                        double raylabStartup, double goal);

// Whether a curve has not reached some goal level (a fraction of its reference's mean `mean`):
// raylab's curves of a peer scene then go on past max_spp (extend_spp), so that the goal there
// gets a ratio, or a bound that decides it, instead of "neither reached it".
bool curveMissesALevel(const std::vector<Checkpoint>& curve, std::span<const double> levels, double mean);

// The curve whose last checkpoint gives raylab's cost per sample per pixel, as an index into
// `renderers`: the variant named kEvenVariant (render.adaptive=false) where the scene has one, else
// raylab's own (index 0). An adaptive curve draws its extra samples where paths are long, so its
// cost per mean sample is the plan's as much as the tracer's (bench/adaptive_sampling.md).
constexpr const char* kEvenVariant = "raylab:even";
size_t tracerCostCurve(std::span<const std::string> renderers);

// A peer scene whose two references' means differ by more than this fraction draws another image
// than raylab's: its times to error compare different integrals, so the summary marks it
// approximate and leaves it out of the time-to-error goal.
constexpr double kApproximateMeanDifference = 0.03;

// How far the peer's (Cycles') reference is from raylab's.
struct PeerMismatch {
    double raylabMean = 0.0;       // of raylab's reference (RGB)
    double peerMean = 0.0;         // of the peer's reference (RGB)
    double meanDifference = 0.0;   // (peer − raylab) / raylab mean
    double rmse = 0.0;             // between the references (RGB)
    bool approximate = false;      // |meanDifference| > kApproximateMeanDifference
};

PeerMismatch peerMismatch(const Image& raylabReference, const Image& peerReference);

// The summary's table of reference mismatches, one row per (scene, mismatch).
std::string peerMismatchTable(const std::vector<std::pair<std::string, PeerMismatch>>& scenes);

} // namespace raylab
