#include "app/split_accounting.h"

#include <algorithm>
#include <cmath>

namespace raylab::ui {

void SplitAccounting::reset(SplitBudget budget) {
    budget_ = budget;
    sides_[0] = sides_[1] = SplitSide{};
}

int SplitAccounting::next() const {
    if (budget_ == SplitBudget::EqualTime) return sides_[1].seconds < sides_[0].seconds ? 1 : 0;
    return sides_[1].spp < sides_[0].spp ? 1 : 0;
}

void SplitAccounting::record(int side, int spp, double seconds) {
    SplitSide& s = sides_[side & 1];
    s.spp += std::uint64_t(std::max(spp, 0));
    s.seconds += seconds;
    ++s.passes;
    s.longestPass = std::max(s.longestPass, seconds);
}

double SplitAccounting::imbalance() const {
    if (budget_ == SplitBudget::EqualTime) return std::abs(sides_[0].seconds - sides_[1].seconds);
    return std::abs(double(sides_[0].spp) - double(sides_[1].spp));
}

double SplitAccounting::bound(int rpp) const {
    if (budget_ == SplitBudget::EqualTime) return std::max(sides_[0].longestPass, sides_[1].longestPass);
    return double(rpp);
}

} // namespace raylab::ui
