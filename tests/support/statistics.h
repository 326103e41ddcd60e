#pragma once
// Small statistics for tests: χ² goodness of fit with pooling, its p-value, Šidák correction
// (src/stats/chi_square.h, shared with the viewer), means and standard errors, least-squares slopes.
#include "stats/chi_square.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace raylab::test {

using stats::chiSquarePValue;
using stats::ChiSquareResult;
using stats::chiSquareTest;
using stats::gammaQ;
using stats::sidak;

inline double mean(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

inline double standardError(const std::vector<double>& v) {
    const double m = mean(v);
    double ss = 0.0;
    for (double x : v) ss += (x - m) * (x - m);
    return std::sqrt(ss / double(v.size() - 1) / double(v.size()));
}

// Least-squares slope of y against x.
inline double slope(const std::vector<double>& x, const std::vector<double>& y) {
    const double mx = mean(x), my = mean(y);
    double sxy = 0.0, sxx = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
    }
    return sxy / sxx;
}

} // namespace raylab::test
