// The split screen's accounting: equal samples alternates, equal time gives the side behind in
// time the next pass, and the two times never drift apart by more than the longest pass.
#include "app/split_accounting.h"

#include <gtest/gtest.h>

#include <random>

namespace raylab::ui {

TEST(SplitAccounting, EqualSamplesAlternatesAndStaysWithinOnePass) {
    SplitAccounting a(SplitBudget::EqualSamples);
    for (int i = 0; i < 100; ++i) {
        const int side = a.next();
        a.record(side, 2, side == 0 ? 0.01 : 0.05);   // B is five times slower: irrelevant here
        EXPECT_LE(a.imbalance(), a.bound(2));
    }
    EXPECT_EQ(a.side(0).spp, 100u);
    EXPECT_EQ(a.side(1).spp, 100u);
}

TEST(SplitAccounting, EqualTimeKeepsTimesWithinTheLongestPass) {
    SplitAccounting a(SplitBudget::EqualTime);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(0.8, 1.25);
    for (int i = 0; i < 2000; ++i) {
        const int side = a.next();
        a.record(side, 1, (side == 0 ? 0.004 : 0.020) * jitter(rng));   // B costs five times A per pass
        ASSERT_LE(a.imbalance(), a.bound(1) + 1e-12) << "pass " << i;
    }
    // Equal time: the cheap side got about five times the samples.
    const double ratio = double(a.side(0).spp) / double(a.side(1).spp);
    EXPECT_NEAR(ratio, 5.0, 0.5);
    EXPECT_NEAR(a.side(0).seconds, a.side(1).seconds, a.bound(1));
    a.reset(SplitBudget::EqualSamples);
    EXPECT_EQ(a.side(0).passes, 0u);
    EXPECT_EQ(a.next(), 0);
}

} // namespace raylab::ui
