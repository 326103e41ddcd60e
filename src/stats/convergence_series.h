#pragma once
// A live convergence curve without a reference image: the error of a progressive image, estimated
// from the image itself at sample counts that (at least) double.
//
// If I_m is the mean of m independent samples per pixel and I_n (n < m) the same run's mean after
// its first n samples, then E|I_m − I_n|² = σ² (m − n) / (m n) and the error we want is
// E|I_m − μ|² = σ² / m, so MSE(I_m) = E|I_m − I_n|² · n / (m − n). Averaged over pixels and colour
// channels this needs two snapshots and no reference. (A derivation of the same idea: the "two
// half buffers" variance estimate, e.g. Rousselle et al. 2012, §3.)
#include "render/image.h"

#include <cstdint>
#include <vector>

namespace raylab::stats {

struct ConvergencePoint {
    double spp = 0.0;
    double seconds = 0.0;     // tracing time to reach spp
    double rmse = 0.0;        // estimated root mean squared error of the image (linear units)
    double relativeRmse = 0.0;   // rmse / the image's mean value
};

class ConvergenceSeries {
public:
    void reset();
    // Would an image at `spp` give a new point? (spp ≥ 2 × the last snapshot's, or no snapshot yet;
    // callers read the image back only then.)
    bool wants(std::uint64_t spp) const;
    // The image after `spp` samples per pixel of one run (reset() between runs).
    void add(std::uint64_t spp, double seconds, const Image& image);
    const std::vector<ConvergencePoint>& points() const { return points_; }
    // Least-squares slope of log(relative RMSE) against log(spp): −0.5 for Monte Carlo; NaN with
    // fewer than two points.
    double slope() const;

private:
    std::vector<ConvergencePoint> points_;
    Image snapshot_;
    std::uint64_t snapshotSpp_ = 0;
};

} // namespace raylab::stats
