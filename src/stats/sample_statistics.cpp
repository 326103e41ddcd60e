#include "stats/sample_statistics.h"

#include <cmath>
#include <cstddef>
#include <numeric>

namespace raylab::stats {

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()); }

double standardError(const std::vector<double>& v) {
    const double m = mean(v);
    double ss = 0.0;
    for (double x : v) ss += (x - m) * (x - m);
    return std::sqrt(ss / double(v.size() - 1) / double(v.size()));
}

double slope(const std::vector<double>& x, const std::vector<double>& y) {
    const double mx = mean(x), my = mean(y);
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
    }
    return sxy / sxx;
}

double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<double> lx, ly;
    for (double v : x) lx.push_back(std::log(v));
    for (double v : y) ly.push_back(std::log(v));
    return slope(lx, ly);
}

} // namespace raylab::stats
