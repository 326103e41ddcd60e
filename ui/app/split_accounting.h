#pragma once
// Who traces next in the A/B split screen, and what each side has been given. Equal samples: the
// side with fewer samples per pixel; equal time: the side with less tracing time. Ties go to A.
// Picking the side that is behind keeps |time A − time B| at most the longest single pass (a pass
// of length d added to the side behind by δ leaves a gap of |d − δ| ≤ max(d, δ)).
#include <cstdint>

namespace raylab::ui {

enum class SplitBudget { EqualSamples, EqualTime };

struct SplitSide {
    std::uint64_t spp = 0;
    double seconds = 0.0;       // tracing time (each pass timed to its end)
    std::uint64_t passes = 0;
    double longestPass = 0.0;   // seconds
};

class SplitAccounting {
public:
    explicit SplitAccounting(SplitBudget budget = SplitBudget::EqualSamples) : budget_(budget) {}
    void reset(SplitBudget budget);
    SplitBudget budget() const { return budget_; }
    int next() const;   // 0 = A, 1 = B
    void record(int side, int spp, double seconds);
    const SplitSide& side(int i) const { return sides_[i & 1]; }
    // |A − B| in the budget's unit (spp or seconds), and the bound the rule above guarantees for
    // it: the largest pass (rpp samples, or the longest pass's time) either side has traced.
    double imbalance() const;
    double bound(int rpp) const;

private:
    SplitBudget budget_;
    SplitSide sides_[2];
};

} // namespace raylab::ui
