// The planning of per-pixel adaptive sampling (render/adaptive_sampling.h), without GL: warm-up,
// the fixed point n ∝ s/√c that minimises the image's MSE in a given time, the floor that keeps
// every block sampled, the error estimate from all samples against half of them, and the pass scale.
#include "render/adaptive_sampling.h"
#include "shaders/include/adaptive_sampling.glsl"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

using namespace raylab;

namespace {

// Passes of rpp samples each, as PathTracer::finishPass counts them; cost 1 per sample unless given.
std::vector<std::uint64_t> simulate(const std::vector<double>& deviation, int passes, std::uint64_t rpp,
                                    std::vector<double> cost = {}) {
    if (cost.empty()) cost.assign(deviation.size(), 1.0);
    std::vector<std::uint64_t> n(deviation.size(), 0);
    for (int p = 0; p < passes; ++p) {
        const std::vector<std::uint8_t> active = activeBlocks(deviation, cost, n);
        for (std::size_t b = 0; b < n.size(); ++b)
            if (active[b]) n[b] += rpp;
    }
    return n;
}

double imageMse(const std::vector<double>& s, const std::vector<std::uint64_t>& n) {
    double sum = 0.0;
    for (std::size_t b = 0; b < s.size(); ++b) sum += s[b] * s[b] / double(n[b]);
    return sum / double(s.size());
}

} // namespace

TEST(AdaptiveSampling, EveryBlockTakesThePassUntilEachHoldsTheWarmUp) {
    const std::vector<double> s = {0.0, 5.0, 1.0};
    const std::vector<std::uint64_t> below = {kAdaptiveWarmupSamples, kAdaptiveWarmupSamples - 1, 100};
    const std::vector<double> c(3, 1.0);
    EXPECT_EQ(activeBlocks(s, c, below), std::vector<std::uint8_t>({1, 1, 1}));
    const std::vector<std::uint64_t> after = {kAdaptiveWarmupSamples, kAdaptiveWarmupSamples, kAdaptiveWarmupSamples};
    EXPECT_EQ(activeBlocks(s, c, after), std::vector<std::uint8_t>({0, 1, 0}));
}

TEST(AdaptiveSampling, BlocksAlikeAllTakeThePass) {
    // No variance anywhere (a furnace), and equal noise per sample held: every block, every pass.
    EXPECT_EQ(activeBlocks(std::vector<double>(5, 0.0), std::vector<double>(5, 3.0), std::vector<std::uint64_t>(5, 64)),
              std::vector<std::uint8_t>(5, 1));
    EXPECT_EQ(activeBlocks(std::vector<double>{0.3, 0.6, 0.9}, std::vector<double>(3, 2.0),
                           std::vector<std::uint64_t>{32, 64, 96}),
              std::vector<std::uint8_t>(3, 1));
}

TEST(AdaptiveSampling, BlocksEndWithSamplesInProportionToTheirNoiseAndTheLeastMse) {
    // Deviations over two decades. After the passes, n/s is alike across the blocks (within two
    // passes' samples of the largest block's share), and the image's MSE, mean s²/n, is within 2 %
    // of the least any spreading of the same total reaches, (mean s)² / (total / blocks), where
    // spreading the total evenly would give mean(s²) / (total / blocks), 2.6 times that.
    const std::vector<double> s = {0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 0.3};
    const std::uint64_t rpp = 4;
    const std::vector<std::uint64_t> n = simulate(s, 4000, rpp);
    const double total = double(std::accumulate(n.begin(), n.end(), std::uint64_t(0)));
    const double perBlock = total / double(s.size());
    const double meanS = std::accumulate(s.begin(), s.end(), 0.0) / double(s.size());
    double meanS2 = 0.0;
    for (double v : s) meanS2 += v * v / double(s.size());
    const double best = meanS * meanS / perBlock;
    const double even = meanS2 / perBlock;
    EXPECT_GT(even / best, 2.5);
    EXPECT_LT(imageMse(s, n) / best, 1.02);
    // Each block's share of the samples is its share of the deviations (the floor, 5 % of the
    // mean, lifts block 0's 0.1 to 0.12), within 10 % and two passes' samples.
    std::vector<double> floored(s);
    for (double& v : floored) v = std::max(v, kAdaptiveDeviationFloor * meanS);
    const double sumFloored = std::accumulate(floored.begin(), floored.end(), 0.0);
    for (std::size_t b = 0; b < s.size(); ++b) {
        const double expected = floored[b] / sumFloored;
        EXPECT_NEAR(double(n[b]) / total, expected, 0.1 * expected + 2.0 * double(rpp) / total) << "block " << b;
    }
}

TEST(AdaptiveSampling, TheGainIsEvenSpreadingsMseOverTheBestSpreadings) {
    // Equal cost: mean(s²) / mean(s)²; no spread or no variance: 1, nothing to gain.
    EXPECT_DOUBLE_EQ(adaptiveGain(std::vector<double>{2.0, 2.0, 2.0}, std::vector<double>(3, 3.0)), 1.0);
    EXPECT_DOUBLE_EQ(adaptiveGain(std::vector<double>(4, 0.0), std::vector<double>(4, 1.0)), 1.0);
    EXPECT_NEAR(adaptiveGain(std::vector<double>{0.0, 5.0, 1.0}, std::vector<double>(3, 1.0)), (26.0 / 3.0) / 4.0, 1e-12);
    // Equal noise, one block four times as dear: mean(c)·mean(s²) / mean(s·√c)² = 2.5 / 1.5².
    EXPECT_NEAR(adaptiveGain(std::vector<double>{1.0, 1.0}, std::vector<double>{1.0, 4.0}), 2.5 / 2.25, 1e-12);
    // It is what the planning reaches: with samples spread by activeBlocks, even spreading's MSE for
    // the same total over the planned MSE comes to the gain (the floor aside, which no block here
    // falls under).
    const std::vector<double> s = {0.5, 1.0, 2.0, 4.0, 8.0};
    const std::vector<std::uint64_t> n = simulate(s, 4000, 4);
    const double perBlock = double(std::accumulate(n.begin(), n.end(), std::uint64_t(0))) / double(s.size());
    double meanS2 = 0.0;
    for (double v : s) meanS2 += v * v / double(s.size());
    EXPECT_NEAR((meanS2 / perBlock) / imageMse(s, n), adaptiveGain(s, std::vector<double>(s.size(), 1.0)), 0.02);
}

TEST(AdaptiveSampling, ADearerBlockTakesFewerSamplesForTheSameNoise) {
    // Equal noise, one block four times as dear per sample (rays): for the least MSE in a given
    // time, n ∝ s/√c, so the cheap block ends with twice the samples; without the cost they would
    // be equal.
    const std::vector<std::uint64_t> n = simulate({1.0, 1.0}, 2000, 4, {1.0, 4.0});
    EXPECT_NEAR(double(n[0]) / double(n[1]), 2.0, 0.1);
    const std::vector<std::uint64_t> same = simulate({1.0, 1.0}, 2000, 4);
    EXPECT_EQ(same[0], same[1]);
}

TEST(AdaptiveSampling, ABlockWithoutVarianceStillTakesSamplesAtTheFloor) {
    // Block 0's first samples all agreed: it goes on at the floor's rate, so a rare bright path
    // there is not missed for good; block 1 takes the rest.
    // Its floored deviation is 5 % of the mean deviation, 0.5, against block 1's 1: n0/n1 → 0.025.
    const std::vector<std::uint64_t> n = simulate({0.0, 1.0}, 2000, 4);
    EXPECT_GT(n[0], kAdaptiveWarmupSamples);
    const double expected = kAdaptiveDeviationFloor * 0.5 / 1.0;
    EXPECT_NEAR(double(n[0]) / double(n[1]), expected, 0.5 * expected);
}

TEST(AdaptiveSampling, TheHalfIsEveryOtherRunOfSamples) {
    // adaptiveHalfCount counts what adaptiveInHalf picks; runs of ADAPTIVE_HALF_RUN alternate.
    unsigned counted = 0;
    for (unsigned n = 0; n < 200; ++n) {
        EXPECT_EQ(glsl::adaptiveHalfCount(n), counted) << n;
        counted += glsl::adaptiveInHalf(n) ? 1u : 0u;
    }
    EXPECT_TRUE(glsl::adaptiveInHalf(0));
    EXPECT_TRUE(glsl::adaptiveInHalf(glsl::ADAPTIVE_HALF_RUN - 1));
    EXPECT_FALSE(glsl::adaptiveInHalf(glsl::ADAPTIVE_HALF_RUN));
    EXPECT_EQ(glsl::adaptiveHalfCount(2 * glsl::ADAPTIVE_HALF_RUN * 5), glsl::ADAPTIVE_HALF_RUN * 5);
}

TEST(AdaptiveSampling, AllAgainstHalfEstimatesTheVarianceOfTheMean) {
    // Independent samples of variance 4 (normal, mean 1): the estimate n·(all − half)²·h/(n − h)
    // averaged over 20 000 pixels is σ² = 4, for n a whole number of half-and-other pairs (48) and
    // not (40: h = 24, n − h = 16). Its standard error is σ²·√2/√20000 = 0.04, so 4 ± 0.2 is five
    // of them; fixed seed.
    std::mt19937 rng(12345);
    std::normal_distribution<double> normal(1.0, 2.0);
    for (const unsigned n : {48u, 40u}) {
        const AdaptiveBlocks blocks{1, 1};
        double sum = 0.0;
        const int pixels = 20000;
        for (int p = 0; p < pixels; ++p) {
            double all = 0.0, half = 0.0;
            for (unsigned i = 0; i < n; ++i) {
                const double v = normal(rng);
                all += v;
                if (glsl::adaptiveInHalf(i)) half += v;
            }
            all /= double(n);
            half /= double(glsl::adaptiveHalfCount(n));
            const std::vector<float> mean = {float(all), float(all), float(all), 1.0f};
            const std::vector<float> halfImage = {float(half), float(half), float(half), 1.0f};
            const std::vector<std::uint64_t> samples = {n};
            const double s = blockNoise(blocks, mean, halfImage, samples).deviation[0];
            sum += s * s;
        }
        EXPECT_NEAR(sum / pixels, 4.0, 0.2) << n << " samples";
    }
}

TEST(AdaptiveSampling, BlockNoiseComesFromItsPixelsAllAgainstHalfAndItsMeanRays) {
    // 5 × 5 pixels: blocks of 4 × 4, so 2 × 2 blocks, the right and top ones cut off. Pixel (x, y)
    // has mean m = x + y (grey) and a half mean m − 0.1·(x + 1), so (all − half)² = 0.01·(x + 1)²,
    // and y + 1 rays per sample. The blocks hold 32, 32, 24 and 16 samples (h = 16, 16, 16, 8:
    // h/(n − h) = 1, 1, 2, 1); pixel (4, 4)'s red half is not finite, counted as no difference.
    const AdaptiveBlocks blocks{5, 5};
    ASSERT_EQ(blocks.count(), 4);
    EXPECT_EQ(blocks.blockOf(4, 0), 1);
    EXPECT_EQ(blocks.blockOf(0, 4), 2);
    EXPECT_EQ(blocks.pixelsIn(0), 16);
    EXPECT_EQ(blocks.pixelsIn(1), 4);
    EXPECT_EQ(blocks.pixelsIn(3), 1);
    std::vector<float> mean(4 * 25), half(4 * 25);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) {
            const std::size_t i = std::size_t(y * 5 + x);
            const float m = float(x + y);
            for (std::size_t c = 0; c < 3; ++c) {
                mean[4 * i + c] = m;
                half[4 * i + c] = m - 0.1f * float(x + 1);
            }
            half[4 * i + 3] = float(y + 1);
        }
    half[4 * 24] = std::numeric_limits<float>::quiet_NaN();
    const std::vector<std::uint64_t> samples = {32, 32, 24, 16};
    const BlockNoise noise = blockNoise(blocks, mean, half, samples);
    ASSERT_EQ(noise.deviation.size(), 4u);
    EXPECT_NEAR(noise.deviation[0], std::sqrt(32 * 0.075), 1e-4);   // x 0–3: 0.01·(1 + 4 + 9 + 16)/4
    EXPECT_NEAR(noise.deviation[1], std::sqrt(32 * 0.25), 1e-4);    // x 4 alone
    EXPECT_NEAR(noise.deviation[2], std::sqrt(24 * 0.075 * 2), 1e-4);
    EXPECT_NEAR(noise.deviation[3], std::sqrt(16 * 0.25 * 2 / 3), 1e-4);   // green and blue only
    EXPECT_DOUBLE_EQ(noise.cost[0], 2.5);                      // y 0–3: rays 1–4
    EXPECT_DOUBLE_EQ(noise.cost[3], 5.0);
    // Before the other half holds a sample there is nothing to compare: no noise yet.
    EXPECT_EQ(blockNoise(blocks, mean, half, std::vector<std::uint64_t>{8, 8, 8, 8}).deviation,
              std::vector<double>(4, 0.0));
    EXPECT_THROW(blockNoise(blocks, mean, std::vector<float>(49), samples), std::invalid_argument);
    EXPECT_THROW(blockNoise(blocks, mean, half, std::vector<std::uint64_t>(3)), std::invalid_argument);
}

TEST(AdaptiveSampling, APassThatFewBlocksTakeGivesThemMoreSamples) {
    // 8 × 8 pixels, four blocks; 40 × 4, ten blocks.
    const AdaptiveBlocks four{8, 8};
    EXPECT_EQ(passScale(four, std::vector<std::uint8_t>{1, 1, 1, 1}), 1u);
    EXPECT_EQ(passScale(four, std::vector<std::uint8_t>{1, 1, 1, 0}), 1u);   // 64/48, rounded down
    EXPECT_EQ(passScale(four, std::vector<std::uint8_t>{1, 0, 1, 0}), 2u);
    EXPECT_EQ(passScale(four, std::vector<std::uint8_t>{0, 0, 0, 1}), 4u);
    EXPECT_EQ(passScale(four, std::vector<std::uint8_t>{0, 0, 0, 0}), 1u);
    const AdaptiveBlocks ten{40, 4};
    std::vector<std::uint8_t> one(10, 0);
    one[3] = 1;
    EXPECT_EQ(passScale(ten, one), kAdaptiveMaxPassScale);
    // A cut-off block counts its pixels: of 5 × 5, the corner pixel's block alone gives 25, the
    // full block 25/16.
    EXPECT_EQ(passScale(AdaptiveBlocks{5, 5}, std::vector<std::uint8_t>{0, 0, 0, 1}), kAdaptiveMaxPassScale);
    EXPECT_EQ(passScale(AdaptiveBlocks{5, 5}, std::vector<std::uint8_t>{1, 0, 0, 0}), 1u);
    EXPECT_THROW(passScale(four, std::vector<std::uint8_t>(3, 1)), std::invalid_argument);
}

TEST(AdaptiveSampling, ABlockFarBehindTakesThePassInMoreRounds) {
    // Sixteen 4 × 4 blocks of 16 × 16 pixels, cost 1, 64 samples each: block 0's deviation is k
    // times the others', so its s/(n·√c) is 16k/(k + 15) times the mean.
    const AdaptiveBlocks blocks{16, 16};
    const std::vector<double> c(16, 1.0);
    const std::vector<std::uint64_t> n(16, 64);
    for (double k : {1.0, 2.0, 3.0, 8.0, 100.0}) {
        std::vector<double> s(16, 1.0);
        s[0] = k;
        const std::vector<std::uint8_t> rounds = passRounds(blocks, s, c, n);
        const double behind = 16.0 * k / (k + 15.0);
        EXPECT_EQ(rounds[0], std::min<std::uint64_t>(std::uint64_t(std::floor(behind)), kAdaptiveMaxRounds)) << k;
        for (std::size_t b = 1; b < 16; ++b) EXPECT_EQ(rounds[b], k == 1.0 ? 1 : 0) << k << ", block " << b;
        // Whoever takes the pass is as activeBlocks says.
        const std::vector<std::uint8_t> active = activeBlocks(s, c, n);
        for (std::size_t b = 0; b < 16; ++b) EXPECT_EQ(rounds[b] > 0, active[b] > 0) << k << ", block " << b;
    }
    // The warm-up and blocks alike: one round each.
    std::vector<std::uint64_t> warm(16, 64);
    warm[5] = kAdaptiveWarmupSamples - 1;
    std::vector<double> s(16, 1.0);
    s[0] = 100.0;
    EXPECT_EQ(passRounds(blocks, s, c, warm), std::vector<std::uint8_t>(16, 1));
    EXPECT_EQ(passRounds(blocks, std::vector<double>(16, 0.0), c, n), std::vector<std::uint8_t>(16, 1));
    EXPECT_THROW(passRounds(blocks, s, c, std::vector<std::uint64_t>(15, 64)), std::invalid_argument);
    EXPECT_THROW(passRounds(blocks, std::vector<double>(15, 1.0), c, n), std::invalid_argument);
}

TEST(AdaptiveSampling, APassInRoundsNeverTracesMoreThanAnEvenPass) {
    // 5 × 5 pixels: blocks of 16, 4, 4 and 1 pixels. The full block far behind would take
    // kAdaptiveMaxRounds × 16 > 25 paths; it is cut back to what an even pass traces.
    const AdaptiveBlocks blocks{5, 5};
    const std::vector<double> s = {10.0, 1.0, 1.0, 0.1};
    const std::vector<std::uint8_t> rounds = passRounds(blocks, s, std::vector<double>(4, 1.0),
                                                        std::vector<std::uint64_t>(4, 64));
    std::uint64_t paths = 0;
    for (int b = 0; b < 4; ++b) paths += rounds[std::size_t(b)] * std::uint64_t(blocks.pixelsIn(b));
    EXPECT_LE(paths, 25u);
    EXPECT_EQ(rounds, std::vector<std::uint8_t>({1, 0, 0, 0}));
    // The pass scale counts a block's rounds: two rounds of one block of four are half the image.
    EXPECT_EQ(passScale(AdaptiveBlocks{8, 8}, std::vector<std::uint8_t>{2, 0, 0, 0}), 2u);
    EXPECT_EQ(passScale(AdaptiveBlocks{8, 8}, std::vector<std::uint8_t>{2, 1, 1, 0}), 1u);
}
