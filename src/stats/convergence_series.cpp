#include "stats/convergence_series.h"

#include "stats/sample_statistics.h"

#include <cmath>
#include <limits>

namespace raylab::stats {

void ConvergenceSeries::reset() {
    points_.clear();
    snapshot_ = Image{};
    snapshotSpp_ = 0;
}

bool ConvergenceSeries::wants(std::uint64_t spp) const {
    return spp > 0 && (snapshotSpp_ == 0 || spp >= 2 * snapshotSpp_);
}

void ConvergenceSeries::add(std::uint64_t spp, double seconds, const Image& image) {
    if (!wants(spp)) return;
    if (snapshotSpp_ > 0 && image.rgba.size() == snapshot_.rgba.size()) {
        double sumSq = 0.0, sum = 0.0;
        std::size_t count = 0;
        for (std::size_t i = 0; i < image.rgba.size(); ++i) {
            if (i % 4 == 3) continue;
            const double a = image.rgba[i], b = snapshot_.rgba[i];
            if (!std::isfinite(a) || !std::isfinite(b)) continue;
            sumSq += (a - b) * (a - b);
            sum += a;
            ++count;
        }
        if (count > 0) {
            const double n = double(snapshotSpp_), m = double(spp);
            ConvergencePoint p;
            p.spp = m;
            p.seconds = seconds;
            p.rmse = std::sqrt(sumSq / double(count) * n / (m - n));
            const double mean = sum / double(count);
            p.relativeRmse = mean > 0.0 ? p.rmse / mean : 0.0;
            points_.push_back(p);
        }
    }
    snapshot_ = image;
    snapshotSpp_ = spp;
}

double ConvergenceSeries::slope() const {
    std::vector<double> x, y;
    for (const ConvergencePoint& p : points_)
        if (p.relativeRmse > 0.0) {
            x.push_back(std::log(p.spp));
            y.push_back(std::log(p.relativeRmse));
        }
    if (x.size() < 2) return std::numeric_limits<double>::quiet_NaN();
    return stats::slope(x, y);
}

} // namespace raylab::stats
