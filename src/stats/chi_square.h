#pragma once
// Pearson's χ² goodness-of-fit test with pooling of sparse cells, its p-value, and the Šidák
// correction for a family of tests. Used by the tests and by the viewer's self-test panel.
#include <vector>

namespace raylab::stats {

// Regularised upper incomplete gamma Q(a, x) = Γ(a, x) / Γ(a).
double gammaQ(double a, double x);

// P(χ²_dof ≥ statistic).
double chiSquarePValue(double statistic, double dof);

// Per-test significance that keeps the family-wise level alpha over `tests` tests (Šidák).
double sidak(double alpha, int tests);

struct ChiSquareResult {
    double statistic = 0.0;
    int dof = 0;
    double pValue = 1.0;
    bool sampleInZeroCell = false;   // an observation where the pdf says none can be: fail outright
};

// Pearson χ² with cells of expected count < minExpected pooled into one (as Nori and Mitsuba do).
ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected = 5.0);

} // namespace raylab::stats
