#include "stats/chi_square.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>

namespace raylab::stats {

// The series for x < a + 1, the continued fraction (modified Lentz) otherwise. Formulas: Press et
// al., Numerical Recipes §6.2.
double gammaQ(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double logPrefix = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000 && std::abs(term) > std::abs(sum) * 1e-15; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return std::max(0.0, 1.0 - sum * std::exp(logPrefix));
    }
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(logPrefix) * h;
}

double chiSquarePValue(double statistic, double dof) { return gammaQ(0.5 * dof, 0.5 * statistic); }

double sidak(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected) {
    std::vector<std::size_t> order(observed.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
    ChiSquareResult r;
    double pooledObs = 0.0, pooledExp = 0.0;
    int cells = 0;
    for (std::size_t i : order) {
        if (expected[i] <= 0.0) {
            if (observed[i] > 0.0) r.sampleInZeroCell = true;
            continue;
        }
        if (expected[i] < minExpected) {
            pooledObs += observed[i];
            pooledExp += expected[i];
            continue;
        }
        r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++cells;
    }
    if (pooledExp > 0.0) {
        r.statistic += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
        ++cells;
    }
    r.dof = std::max(cells - 1, 1);
    r.pValue = chiSquarePValue(r.statistic, r.dof);
    return r;
}

} // namespace raylab::stats
