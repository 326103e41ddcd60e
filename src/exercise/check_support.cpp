#include "exercise/check_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace raylab::exercise {

bool agrees(double got, double want, double tolerance) {
    if (std::isnan(got) || std::isnan(want)) return false;
    if (std::isinf(want) || std::isinf(got)) return got == want;
    return std::abs(got - want) <= tolerance * std::max(1.0, std::abs(want));
}

Comparison compare(const std::vector<double>& got, const std::vector<double>& want, double tolerance) {
    Comparison c;
    c.total = int(want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        if (std::isfinite(got[i]) && std::isfinite(want[i])) c.maxError = std::max(c.maxError, std::abs(got[i] - want[i]));
        if (agrees(got[i], want[i], tolerance)) continue;
        if (c.firstWrong < 0) c.firstWrong = int(i);
        ++c.wrong;
    }
    return c;
}

std::string diagnose(const std::vector<double>& got, const std::vector<Mistake>& mistakes, double tolerance) {
    for (const Mistake& m : mistakes) {
        bool all = !m.values.empty();
        // A mistake that overflows overflows the same way: non-finite values agree with each other.
        for (std::size_t i = 0; all && i < m.values.size(); ++i)
            all = agrees(got[i], m.values[i], tolerance) || (!std::isfinite(got[i]) && !std::isfinite(m.values[i]));
        if (all) return m.message;
    }
    return "";
}

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string describe(const Comparison& c, const std::string& items) {
    return std::to_string(c.wrong) + " of " + std::to_string(c.total) + " " + items + " wrong, max error " + num(c.maxError);
}

} // namespace raylab::exercise
