// The convergence series estimates an image's error from its own snapshots at doubling sample
// counts: on synthetic progressive images with known noise it must find the true RMSE and the
// Monte Carlo slope −1/2, and it must not be fooled by a biased (noise-free) image.
#include "stats/convergence_series.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace raylab;

namespace {

// A progressive mean over per-pixel samples μ_p + σ·N(0, 1), fed at spp 1, 2, ... 256.
struct Progressive {
    Image sum;
    Image mean;
    std::mt19937 rng{12345};
    std::normal_distribution<float> noise{0.0f, 1.0f};
    float sigma;
    explicit Progressive(float s) : sum(64, 64), mean(64, 64), sigma(s) {}
    float mu(std::size_t i) const { return 0.5f + 0.25f * float(i % 7) / 6.0f; }
    void addSample(int spp) {
        for (std::size_t i = 0; i < sum.rgba.size(); ++i) {
            if (i % 4 == 3) continue;
            sum.rgba[i] += mu(i) + sigma * noise(rng);
            mean.rgba[i] = sum.rgba[i] / float(spp);
        }
    }
};

} // namespace

TEST(ConvergenceSeries, FindsTheTrueErrorAndTheMonteCarloSlope) {
    Progressive p(0.3f);
    stats::ConvergenceSeries series;
    int reads = 0;
    for (int spp = 1; spp <= 256; ++spp) {
        p.addSample(spp);
        if (series.wants(std::uint64_t(spp))) {
            series.add(std::uint64_t(spp), spp * 0.01, p.mean);
            ++reads;
        }
    }
    EXPECT_EQ(reads, 9);   // 1, 2, 4, ..., 256: a readback only at doublings
    ASSERT_EQ(series.points().size(), 8u);
    const double meanValue = 0.5 + 0.25 * 0.5;   // about: the μ pattern's mean
    for (const auto& pt : series.points()) {
        const double truth = 0.3 / std::sqrt(pt.spp);
        // 64·64·3 = 12288 pixel values: the estimate's relative spread is about √(2/12288) ≈ 1.3%
        // (plus the snapshot's share); 6% is more than four of those.
        EXPECT_NEAR(pt.rmse / truth, 1.0, 0.06) << "spp " << pt.spp;
        EXPECT_NEAR(pt.relativeRmse, pt.rmse / meanValue, 0.02 * pt.rmse / meanValue + 1e-3);
    }
    EXPECT_NEAR(series.slope(), -0.5, 0.03);
}

TEST(ConvergenceSeries, UnevenCheckpointsUseTheGeneralFormula) {
    // Snapshots at 1, 3, 7, ... (whenever a frame happens to see ≥ twice the last count).
    Progressive p(0.2f);
    stats::ConvergenceSeries series;
    for (int spp = 1; spp <= 300; ++spp) {
        p.addSample(spp);
        if (spp % 3 == 1 && series.wants(std::uint64_t(spp))) series.add(std::uint64_t(spp), 0.0, p.mean);
    }
    ASSERT_GE(series.points().size(), 5u);
    for (const auto& pt : series.points()) EXPECT_NEAR(pt.rmse / (0.2 / std::sqrt(pt.spp)), 1.0, 0.06) << pt.spp;
}

TEST(ConvergenceSeries, ANoiseFreeImageHasNoError) {
    Progressive p(0.0f);
    stats::ConvergenceSeries series;
    for (int spp = 1; spp <= 16; ++spp) {
        p.addSample(spp);
        series.add(std::uint64_t(spp), 0.0, p.mean);   // add() ignores what it does not want
    }
    ASSERT_EQ(series.points().size(), 4u);
    for (const auto& pt : series.points()) EXPECT_LT(pt.rmse, 1e-6);
    series.reset();
    EXPECT_TRUE(series.points().empty());
    EXPECT_TRUE(series.wants(1));
}
