#pragma once
// What every check does with its numbers: compare a pupil's values with the right ones, and find
// the known mistake, if any, that explains them all.
#include "exercise/checks.h"

#include <functional>
#include <string>
#include <vector>

namespace raylab::exercise {

// |got − want| ≤ tolerance · max(1, |want|); NaN never agrees.
bool agrees(double got, double want, double tolerance);

struct Comparison {
    int total = 0;
    int wrong = 0;
    int firstWrong = -1;
    double maxError = 0.0;   // largest |got − want| over the finite pairs
};
Comparison compare(const std::vector<double>& got, const std::vector<double>& want, double tolerance);

// A known mistake: what it is, and the values a function with that mistake returns.
struct Mistake {
    std::string message;
    std::vector<double> values;
};
// The first mistake whose values all agree with `got`, or "".
std::string diagnose(const std::vector<double>& got, const std::vector<Mistake>& mistakes, double tolerance);

// "3 of 212 wrong, max error 2.1e-03"
std::string describe(const Comparison& c, const std::string& items);
// A short number: 6 significant digits.
std::string num(double v);

} // namespace raylab::exercise
