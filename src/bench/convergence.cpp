#include "bench/convergence.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace raylab {

std::vector<Checkpoint> runConvergence(PathTracer& tracer, int rpp, std::uint64_t maxSpp,
                                       const Image& reference) {
    using Clock = std::chrono::steady_clock;
    tracer.reset();
    std::vector<Checkpoint> curve;
    double seconds = 0.0;
    std::uint64_t next = 1;
    while (tracer.samplesPerPixel() < maxSpp) {
        const std::uint64_t target = std::min(next, maxSpp);
        const auto start = Clock::now();
        while (tracer.samplesPerPixel() < target)
            tracer.renderPass(int(std::min<std::uint64_t>(std::uint64_t(rpp), target - tracer.samplesPerPixel())));
        seconds += std::chrono::duration<double>(Clock::now() - start).count();
        curve.push_back({tracer.samplesPerPixel(), seconds, imageError(tracer.readImage(), reference)});
        next *= 2;
    }
    return curve;
}

double timeToReach(const std::vector<Checkpoint>& curve, double targetRmse) {
    // The first crossing, interpolated log–log between its neighbours. A progressive curve's
    // times only grow, so that is the answer; a peer's checkpoints are separate runs whose times
    // jitter, and a later run that reached the target sooner is the cheaper way to reach it.
    double best = -1.0;
    for (size_t i = 0; i < curve.size(); ++i) {
        if (curve[i].error.rmse > targetRmse) continue;
        double t = curve[i].seconds;
        if (best < 0.0 && i > 0) {
            const Checkpoint& a = curve[i - 1];
            const Checkpoint& b = curve[i];
            const double la = std::log(a.error.rmse), lb = std::log(b.error.rmse);
            const double f = la == lb ? 1.0 : (la - std::log(targetRmse)) / (la - lb);
            t = std::exp(std::log(a.seconds) + f * (std::log(b.seconds) - std::log(a.seconds)));
        }
        best = best < 0.0 ? t : std::min(best, t);
    }
    return best;
}

double efficiency(const Checkpoint& c) {
    return c.error.mse > 0.0 && c.seconds > 0.0 ? 1.0 / (c.error.mse * c.seconds) : 0.0;
}

double convergenceSlope(const std::vector<Checkpoint>& curve) {
    // Least squares of log RMSE on log spp over the checkpoints with an error: an exact one
    // (RMSE 0, e.g. a furnace's first checkpoints) has no logarithm.
    double mx = 0, my = 0;
    int n = 0;
    for (const Checkpoint& c : curve)
        if (c.error.rmse > 0.0) {
            mx += std::log(double(c.spp));
            my += std::log(c.error.rmse);
            ++n;
        }
    if (n < 2) return 0.0;
    mx /= double(n);
    my /= double(n);
    double sxy = 0, sxx = 0;
    for (const Checkpoint& c : curve) {
        if (!(c.error.rmse > 0.0)) continue;
        const double x = std::log(double(c.spp)) - mx;
        sxy += x * (std::log(c.error.rmse) - my);
        sxx += x * x;
    }
    return sxx > 0 ? sxy / sxx : 0.0;
}

std::vector<Checkpoint> meanOverSeeds(std::span<const std::vector<Checkpoint>> curves) {
    if (curves.empty()) return {};
    std::vector<Checkpoint> mean(curves.front().size());
    for (const std::vector<Checkpoint>& c : curves) {
        if (c.size() != mean.size()) throw std::invalid_argument("meanOverSeeds: curves of different lengths");
        for (size_t i = 0; i < c.size(); ++i) {
            if (c[i].spp != curves.front()[i].spp)
                throw std::invalid_argument("meanOverSeeds: checkpoints at different spp");
            mean[i].spp = c[i].spp;
            mean[i].seconds += c[i].seconds;
            mean[i].error.mse += c[i].error.mse;
            mean[i].error.relMse += c[i].error.relMse;
        }
    }
    const double n = double(curves.size());
    for (Checkpoint& p : mean) {
        p.seconds /= n;
        p.error.mse /= n;
        p.error.relMse /= n;
        p.error.rmse = std::sqrt(p.error.mse);
    }
    return mean;
}

TimeToErrorGoal timeToErrorGoal(const std::vector<Checkpoint>& raylab, double raylabStartup,
                                const std::vector<Checkpoint>& peer, double raylabTarget, double peerTarget,
                                double goal) {
    using V = TimeToErrorGoal::Verdict;
    using B = TimeToErrorGoal::Bound;
    TimeToErrorGoal g;
    const double tr = timeToReach(raylab, raylabTarget);
    g.peerSeconds = timeToReach(peer, peerTarget);
    if (tr >= 0.0) g.raylabSeconds = tr + raylabStartup;
    if (g.raylabSeconds > 0.0 && g.peerSeconds >= 0.0) {
        g.bound = B::Exact;
        g.ratio = g.peerSeconds / g.raylabSeconds;
        g.verdict = g.ratio >= goal ? V::Met : V::NotMet;
    } else if (g.raylabSeconds > 0.0 && !peer.empty()) {
        // The peer needs more samples than its longest run, which took at least this long.
        g.bound = B::AtLeast;
        g.ratio = peer.back().seconds / g.raylabSeconds;
        if (g.ratio >= goal) g.verdict = V::Met;
    } else if (g.peerSeconds >= 0.0 && !raylab.empty()) {
        // raylab's curve is progressive: it gets there after its last checkpoint, if at all.
        g.bound = B::AtMost;
        g.ratio = g.peerSeconds / (raylab.back().seconds + raylabStartup);
        if (g.ratio < goal) g.verdict = V::NotMet;
    }
    return g;
}

TimeToErrorGoal timeToErrorGoalAgainstFastest(const std::vector<Checkpoint>& raylab, double raylabStartup,
                                              std::span<const std::vector<Checkpoint>> peers, double raylabTarget,
                                              double peerTarget, double goal, size_t* which) {
    if (peers.empty()) throw std::invalid_argument("timeToErrorGoalAgainstFastest: no peer curve");
    TimeToErrorGoal best;
    double bestSeconds = 0.0;
    for (size_t i = 0; i < peers.size(); ++i) {
        const TimeToErrorGoal g = timeToErrorGoal(raylab, raylabStartup, peers[i], raylabTarget, peerTarget, goal);
        const double seconds = g.peerSeconds >= 0.0      ? g.peerSeconds
                               : peers[i].empty()        ? std::numeric_limits<double>::infinity()
                                                         : peers[i].back().seconds;
        if (i == 0 || seconds < bestSeconds) {
            best = g;
            bestSeconds = seconds;
            if (which) *which = i;
        }
    }
    return best;
}

bool peerCurveUndecided(const std::vector<Checkpoint>& raylab, const std::vector<Checkpoint>& peer,
                        std::span<const double> levels, double raylabMean, double peerMean,
                        double raylabStartup, double goal) {
    // Undecided as the goal table itself would say: raylab got there, the peer not, and no bound.
    for (double l : levels) {
        const TimeToErrorGoal g = timeToErrorGoal(raylab, raylabStartup, peer, l * raylabMean, l * peerMean, goal);
        if (g.raylabSeconds > 0.0 && g.peerSeconds < 0.0 && g.verdict == TimeToErrorGoal::Verdict::Open) return true;
    }
    return false;
}

bool curveMissesALevel(const std::vector<Checkpoint>& curve, std::span<const double> levels, double mean) {
    for (double l : levels)
        if (timeToReach(curve, l * mean) < 0.0) return true;
    return false;
}

PeerMismatch peerMismatch(const Image& raylabReference, const Image& peerReference) {
    PeerMismatch m;
    m.raylabMean = imageMean(raylabReference);
    m.peerMean = imageMean(peerReference);
    m.meanDifference = m.raylabMean > 0.0 ? (m.peerMean - m.raylabMean) / m.raylabMean : 0.0;
    m.rmse = imageError(peerReference, raylabReference).rmse;
    m.approximate = std::abs(m.meanDifference) > kApproximateMeanDifference;
    return m;
}

std::string peerMismatchTable(const std::vector<std::pair<std::string, PeerMismatch>>& scenes) {
    const auto fmt = [](const char* f, double v) {
        char buf[64];
        std::snprintf(buf, sizeof buf, f, v);
        return std::string(buf);
    };
    std::ostringstream out;
    out << "| scene | raylab reference mean | Cycles reference mean | mean difference | RMSE between them | "
           "RMSE, % of the mean | comparison |\n|---|---|---|---|---|---|---|\n";
    for (const auto& [name, m] : scenes)
        out << "| " << name << " | " << fmt("%.4g", m.raylabMean) << " | " << fmt("%.4g", m.peerMean) << " | "
            << fmt("%+.2f %%", 100.0 * m.meanDifference) << " | " << fmt("%.4g", m.rmse) << " | "
            << fmt("%.1f %%", m.raylabMean > 0.0 ? 100.0 * m.rmse / m.raylabMean : 0.0) << " | "
            << (m.approximate ? "approximate: means differ by more than " +
                                    fmt("%.0f %%", 100.0 * kApproximateMeanDifference) +
                                    ", out of the time-to-error goal"
                              : std::string("same image"))
            << " |\n";
    return out.str();
}

size_t tracerCostCurve(std::span<const std::string> renderers) {
    const auto even = std::find(renderers.begin(), renderers.end(), kEvenVariant);
    return even == renderers.end() ? 0 : size_t(even - renderers.begin());
}

} // namespace raylab
