// Russian roulette with one number per path (russian_roulette.glsl), the very functions the tracer
// runs: unbiased with path-dependent survival probabilities, and with sobol its path lengths are
// stratified, so a roulette-only integrand (the closed furnace) converges as a 1D integral does.
#include "shaders/include/russian_roulette.glsl"
#include "shaders/include/sampler.glsl"

#include "stats/sample_statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

using namespace raylab::glsl;
namespace stats = raylab::stats;

namespace {

// The closed furnace (scenes/closed_furnace.json) as the integrator plays it: each bounce adds
// Le·beta, the BSDF sample multiplies beta by the albedo, and from bounce rrDepth − 1 on the path
// plays roulette with `number(bounce)`. Exact value Le / (1 − albedo) less the a^(maxBounces+1) tail.
struct Furnace {
    float le = 0.5f, albedo = 0.5f;
    int maxBounces = 64, rrDepth = 3;
};

// `survivals`, when given, counts the roulettes the path survived.
double furnacePath(const Furnace& f, const std::function<float(int)>& number, bool oneNumber,
                   int* survivals = nullptr) {
    vec3 beta(1.0f);
    float survival = 1.0f;
    double radiance = 0.0;
    if (survivals) *survivals = 0;
    for (int bounce = 0;; ++bounce) {
        radiance += double(f.le) * beta.x;
        if (bounce >= f.maxBounces) break;
        beta *= f.albedo;
        if (bounce + 1 >= f.rrDepth) {
            const float q = rouletteProbability(beta);
            // oneNumber: the path's number against the product of q's; else a coin per bounce.
            float perBounce = 1.0f;
            const bool survived = oneNumber ? rouletteSurvives(number(0), q, survival)
                                            : rouletteSurvives(number(bounce), q, perBounce);
            if (!survived) break;
            if (survivals) ++*survivals;
            beta /= q;
        }
    }
    return radiance;
}

// Q_k, the probability that a furnace path survives its first k + 1 roulettes: every furnace path
// that lives has the same beta, so the q's are one sequence.
std::vector<double> furnaceSurvival(const Furnace& f, int roulettes) {
    std::vector<double> Q;
    vec3 beta(1.0f);
    double product = 1.0;
    for (int bounce = 0; int(Q.size()) < roulettes; ++bounce) {
        beta *= f.albedo;
        if (bounce + 1 < f.rrDepth) continue;
        const float q = rouletteProbability(beta);
        product *= double(q);
        Q.push_back(product);
        beta /= q;
    }
    return Q;
}

// The sobol number a furnace path of `pixel` and sample s reads at `bounce` (bounce 0's slot is
// SAMPLE_DIM_ROULETTE, the one-number roulette's; the others are the per-bounce coins' slots).
float sobolRouletteNumber(uvec2 pixel, uint s, uint seed, int bounce) {
    return sobolSample1D(pixel, s, sampleDim(bounce, SAMPLE_BOUNCE_ROULETTE), seed);
}

} // namespace

TEST(RussianRoulette, SurvivalIsTheFourthRootOfTheLargestThroughputAtMost095) {
    // The rule of rouletteProbability (bench/samplers.md, "The roulette's survival probability"):
    // the largest component decides, its fourth root is q, and 0.95 caps it.
    EXPECT_FLOAT_EQ(rouletteProbability(vec3(0.0625f, 0.01f, 0.0f)), 0.5f);
    EXPECT_FLOAT_EQ(rouletteProbability(vec3(0.01f, 0.0081f, 0.3f)), float(std::pow(0.3, 0.25)));
    EXPECT_FLOAT_EQ(rouletteProbability(vec3(0.2f, 0.9f, 0.5f)), 0.95f);   // 0.9^(1/4) = 0.974
    EXPECT_FLOAT_EQ(rouletteProbability(vec3(3.0f, 0.0f, 0.0f)), 0.95f);
    EXPECT_EQ(rouletteProbability(vec3(0.0f)), 0.0f);   // nothing left to carry: the path ends
}

TEST(RussianRoulette, OneNumberPerPathIsUnbiasedWithPathDependentProbabilities) {
    // Each bounce's albedo is drawn from the path's PCG stream in [0.2, 0.95], so q differs from
    // path to path and bounce to bounce; with Le = 1 the estimate's mean is Σ_k E[a]^k over bounces
    // 0 … 12 (the albedos independent, E[a] = 0.575). 2^18 paths, a 4.5σ bound (two-sided
    // p ≈ 7e-6). A fresh number per bounce against the product would end paths too early: the
    // mean fell to 1.86 (seen failing so, when q was max(β) itself).
    const int maxBounces = 12, rrDepth = 1;
    const uint n = 1u << 18;
    double sum = 0.0, sumSq = 0.0;
    for (uint i = 0; i < n; ++i) {
        Rng rng = rngCreate(uvec2(i & 511u, i >> 9u), 0u, 11u);
        const float u = rngNextFloat(rng);   // the path's one roulette number
        vec3 beta(1.0f);
        float survival = 1.0f;
        double radiance = 0.0;
        for (int bounce = 0;; ++bounce) {
            radiance += beta.x;
            if (bounce >= maxBounces) break;
            beta *= 0.2f + 0.75f * rngNextFloat(rng);
            if (bounce + 1 >= rrDepth) {
                const float q = rouletteProbability(beta);
                if (!rouletteSurvives(u, q, survival)) break;
                beta /= q;
            }
        }
        sum += radiance, sumSq += radiance * radiance;
    }
    const double mean = sum / n, variance = sumSq / n - mean * mean;
    double exact = 0.0;
    for (int k = 0; k <= maxBounces; ++k) exact += std::pow(0.575, k);
    EXPECT_NEAR(mean, exact, 4.5 * std::sqrt(variance / n));
}

TEST(RussianRoulette, SobolPathLengthsAreStratifiedInEachPixel) {
    // The closed furnace's survival probabilities Q_k (furnaceSurvival): over 256 sobol samples of
    // a pixel, the paths alive after each of the first six roulettes are N·Q_k to within one, since
    // one Owen-scrambled Sobol dimension puts one point in each interval of width 1/256. Coins from
    // each bounce's own dimension (the layout's unused per-bounce slots) are independent across
    // bounces and miss by several paths: the check can tell them apart.
    const Furnace f;
    const uint n = 256;
    const int roulettes = 6;
    const std::vector<double> Q = furnaceSurvival(f, roulettes);
    for (bool oneNumber : {true, false}) {
        double worst = 0.0;
        for (uint px = 0; px < 8; ++px) {
            std::vector<int> alive(size_t(f.maxBounces + 2), 0);
            for (uint s = 0; s < n; ++s) {
                const auto number = [&](int bounce) { return sobolRouletteNumber(uvec2(px, 5u), s, 3u, bounce); };
                int survivals = 0;
                furnacePath(f, number, oneNumber, &survivals);
                for (int k = 0; k < survivals; ++k) ++alive[size_t(k)];
            }
            for (int k = 0; k < roulettes; ++k)
                worst = std::max(worst, std::abs(alive[size_t(k)] - n * Q[size_t(k)]));
        }
        if (oneNumber) {
            EXPECT_LT(worst, 1.0) << "one number per path";
        } else {
            EXPECT_GT(worst, 2.0) << "a coin per bounce";
        }
    }
}

TEST(RussianRoulette, SobolClosedFurnaceConvergesAsAOneDimensionalIntegral) {
    // The closed furnace's only variance is the roulette's. With one sobol number per path the
    // estimate is a step function of that number: RMSE over 64 pixels at N = 16 … 1024 falls with a
    // slope near −1 (must be steeper than −0.8); with a coin per bounce the interactions between
    // bounces are independent noise and the slope stays near −0.5 (printed, not checked).
    const Furnace f;
    const double exact = double(f.le) / (1.0 - double(f.albedo));
    const std::vector<double> ns = {16, 32, 64, 128, 256, 512, 1024};
    for (bool oneNumber : {true, false}) {
        std::vector<double> errors;
        for (double nd : ns) {
            const uint n = uint(nd);
            double mse = 0.0;
            for (uint px = 0; px < 64; ++px) {
                double sum = 0.0;
                for (uint s = 0; s < n; ++s) {
                    const auto number = [&](int bounce) {
                        return sobolRouletteNumber(uvec2(px % 8u, px / 8u), s, 1u, bounce);
                    };
                    sum += furnacePath(f, number, oneNumber);
                }
                mse += std::pow(sum / n - exact, 2.0);
            }
            errors.push_back(std::sqrt(mse / 64.0));
        }
        const double slope = stats::logLogSlope(ns, errors);
        std::printf("%s: closed furnace RMSE slope %.3f\n", oneNumber ? "one number" : "coin per bounce", slope);
        if (oneNumber) {
            EXPECT_LT(slope, -0.8);
        }
    }
}
