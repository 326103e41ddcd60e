// The samplers of sampler.glsl on the CPU, the very code the tracer runs: each is uniform, the
// stratified ones spread their first points more evenly and converge faster on a smooth integrand,
// and zsobol spreads the error of neighbouring pixels apart (blue noise across the screen).
#include "shaders/include/sampler.glsl"

#include "stats/sample_statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <vector>

using namespace raylab::glsl;
namespace stats = raylab::stats;

namespace {

enum class Kind { Independent, Stratified, Sobol, ZSobol };
constexpr Kind kKinds[] = {Kind::Independent, Kind::Stratified, Kind::Sobol, Kind::ZSobol};
const char* name(Kind k) {
    const char* names[] = {"independent", "stratified", "sobol", "zsobol"};
    return names[int(k)];
}

// Point `index` of dimension pair `dim` of a pixel, as the tracer compiled with that sampler sees
// it; independent is the PCG stream of the pixel's sample, its numbers taken in layout order.
vec2 point2D(Kind kind, uvec2 pixel, uint index, uint dim, uint seed, uint count) {
    switch (kind) {
    case Kind::Stratified: return stratifiedSample2D(pixel, index, dim, seed, count);
    case Kind::Sobol: return vec2(sobolSample1D(pixel, index, dim, seed), sobolSample1D(pixel, index, dim + 1u, seed));
    case Kind::ZSobol: return zsobolSample2D(pixel, index, dim, seed, count);
    default: {
        Rng rng = rngCreate(pixel, index, seed);
        for (uint d = 0; d < dim; ++d) rngNextFloat(rng);
        return rngNext2(rng);
    }
    }
}

// L2 star discrepancy of 2D points (Warnock 1972's closed form).
double l2StarDiscrepancy(const std::vector<vec2>& p) {
    const double n = double(p.size());
    double a = 0.0, b = 0.0;
    for (const vec2& x : p) a += (1.0 - double(x.x) * x.x) * (1.0 - double(x.y) * x.y) / 4.0;
    for (const vec2& x : p)
        for (const vec2& y : p) b += (1.0 - std::max(double(x.x), double(y.x))) * (1.0 - std::max(double(x.y), double(y.y)));
    return std::sqrt(1.0 / 9.0 - 2.0 * a / n + b / (n * n));
}

// Mean L2 star discrepancy of the first n points of dimension pair dim over `pixels` pixels.
double meanDiscrepancy(Kind kind, uint dim, uint n, int pixels) {
    double sum = 0.0;
    for (int i = 0; i < pixels; ++i) {
        std::vector<vec2> pts;
        for (uint s = 0; s < n; ++s) pts.push_back(point2D(kind, uvec2(uint(i) % 8u, uint(i) / 8u), s, dim, 7u, n));
        sum += l2StarDiscrepancy(pts);
    }
    return sum / pixels;
}

// RMSE over `pixels` independent pixels (seeds) of the n-sample estimate of ∫∫ f over the square.
double rmse(Kind kind, uint dim, uint n, int pixels, const std::function<double(vec2)>& f, double exact) {
    double sum2 = 0.0;
    for (int i = 0; i < pixels; ++i) {
        double est = 0.0;
        for (uint s = 0; s < n; ++s) est += f(point2D(kind, uvec2(uint(i), 3u), s, dim, 11u, n));
        est /= n;
        sum2 += (est - exact) * (est - exact);
    }
    return std::sqrt(sum2 / pixels);
}

} // namespace

TEST(Sampler, EveryDimensionIsUniform) {
    // Mean and variance of 4096 points (64 pixels × 64 samples) in a pixel pair, a bounce's BSDF
    // pair and a deep bounce's light pair: U(0,1) has mean 1/2 (standard error 0.0045 for
    // independent points) and variance 1/12; 4.5 standard errors over 18 checks is p < 1e-4.
    for (Kind kind : kKinds)
        for (uint dim : {SAMPLE_DIM_PIXEL, sampleDim(0, SAMPLE_BOUNCE_BSDF), sampleDim(5, SAMPLE_BOUNCE_LIGHT)}) {
            double m[2] = {0, 0}, v[2] = {0, 0};
            int n = 0;
            for (uint px = 0; px < 64; ++px)
                for (uint s = 0; s < 64; ++s, ++n) {
                    const vec2 u = point2D(kind, uvec2(px, 1u), s, dim, 5u, 64u);
                    ASSERT_TRUE(u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f) << name(kind);
                    for (int c = 0; c < 2; ++c) m[c] += u[c], v[c] += double(u[c]) * u[c];
                }
            for (int c = 0; c < 2; ++c) {
                m[c] /= n;
                v[c] = v[c] / n - m[c] * m[c];
                EXPECT_NEAR(m[c], 0.5, 4.5 * std::sqrt(1.0 / 12.0 / n)) << name(kind) << " dim " << dim + c;
                EXPECT_NEAR(v[c], 1.0 / 12.0, 0.01) << name(kind) << " dim " << dim + c;
            }
        }
}

TEST(Sampler, OneDimensionalStrataAreEachTakenOnce) {
    // stratified in 1D: the first `count` samples of a pixel fall one in each stratum.
    for (uint count : {1u, 7u, 64u}) {
        std::vector<int> hits(count, 0);
        for (uint s = 0; s < count; ++s)
            ++hits[size_t(stratifiedSample1D(uvec2(3, 4), s, sampleDim(2, SAMPLE_BOUNCE_ROULETTE), 9u, count) * float(count))];
        EXPECT_EQ(*std::min_element(hits.begin(), hits.end()), 1) << count;
    }
}

TEST(Sampler, SobolIsAZeroTwoNetInEachPixel) {
    // Owen-scrambled Sobol dims 0 and 1 keep their (0,2)-sequence property (Burley 2020, §3): the
    // first 256 points of a pixel fill each of 16 × 16 cells exactly once. zsobol's pixel takes an
    // aligned block of 256 indices of one such sequence: the same holds, in every pair.
    for (Kind kind : {Kind::Sobol, Kind::ZSobol})
        for (uint dim : {SAMPLE_DIM_PIXEL, sampleDim(3, SAMPLE_BOUNCE_BSDF)})
            for (uint px = 0; px < 4; ++px) {
                std::vector<int> cells(256, 0);
                for (uint s = 0; s < 256; ++s) {
                    const vec2 u = point2D(kind, uvec2(px, 2u), s, dim, 1u, 256u);
                    ++cells[size_t(u.x * 16.0f) + 16 * size_t(u.y * 16.0f)];
                }
                EXPECT_EQ(*std::min_element(cells.begin(), cells.end()), 1) << name(kind) << " pixel " << px;
                EXPECT_EQ(*std::max_element(cells.begin(), cells.end()), 1) << name(kind) << " pixel " << px;
            }
}

TEST(Sampler, SobolBitsAreTheGeneratorMatrixTimesTheIndex) {
    // sobolBits takes dimension 0 by reversing the index's bits and dimension 1 by its closed form
    // (Pascal's triangle mod 2): each must be its matrix's product, as dimensions 2 and 3 are, for
    // indices with every bit in play.
    for (uint dim = 0; dim < 4; ++dim)
        for (uint k = 0; k < 4096; ++k) {
            const uint index = k < 2048 ? k : pcg4d(uvec4(k, dim, 7u, 0u)).x;
            uint product = 0;
            for (uint b = 0; b < 32; ++b)
                if ((index >> b) & 1u) product ^= SOBOL_MATRICES[dim * 32 + b];
            ASSERT_EQ(sobolBits(index, dim), product) << "dim " << dim << " index " << index;
        }
}

TEST(Sampler, ZSobolPermutesDigitsByAllTwentyFourPermutations) {
    std::vector<uint> seen;
    for (uint p = 0; p < 24; ++p) {
        const uint perm = zsobolPermutation(p);
        uint digits = 0;
        for (uint k = 0; k < 4; ++k) digits |= 1u << ((perm >> (2u * k)) & 3u);
        EXPECT_EQ(digits, 0xfu) << "permutation " << p << " is a bijection of 0-3";
        seen.push_back(perm);
    }
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(std::unique(seen.begin(), seen.end()), seen.end()) << "each permutation once";
}

TEST(Sampler, ZSobolPixelsOfAQuadTakeComplementaryStrata) {
    // At 1 spp zsobol's 2 × 2 pixel quads hold 4 consecutive indices of a (0,2)-sequence: the
    // four points of a quad fall one in each quadrant of the unit square (Ahmed & Wonka 2020, §4).
    // With the Morton order dropped (every pixel index 0) the quads would repeat one point.
    for (uint dim : {SAMPLE_DIM_PIXEL, sampleDim(0, SAMPLE_BOUNCE_LIGHT)})
        for (uint q = 0; q < 16; ++q) {
            int quadrants[4] = {0, 0, 0, 0};
            for (uint k = 0; k < 4; ++k) {
                const vec2 u = zsobolSample2D(uvec2(2u * q + (k & 1u), 6u + (k >> 1u)), 0u, dim, 3u, 1u);
                ++quadrants[int(u.x * 2.0f) + 2 * int(u.y * 2.0f)];
            }
            for (int c : quadrants) EXPECT_EQ(c, 1) << "quad " << q << " dim " << dim;
        }
}

TEST(Sampler, ZSobolIsBitForBitAFunctionOfPixelIndexDimensionAndSeed) {
    // The same arguments give the same number; another seed, another round or another pixel
    // another one (no pixels or rounds share their samples).
    const vec2 a = zsobolSample2D(uvec2(5, 9), 3u, SAMPLE_DIM_LENS, 1u, 16u);
    EXPECT_EQ(a, zsobolSample2D(uvec2(5, 9), 3u, SAMPLE_DIM_LENS, 1u, 16u));
    EXPECT_NE(a, zsobolSample2D(uvec2(5, 9), 3u, SAMPLE_DIM_LENS, 2u, 16u));
    EXPECT_NE(a, zsobolSample2D(uvec2(5, 9), 3u + 16u, SAMPLE_DIM_LENS, 1u, 16u));
    EXPECT_NE(a, zsobolSample2D(uvec2(5, 10), 3u, SAMPLE_DIM_LENS, 1u, 16u));
}

TEST(Sampler, StratifiedAndSobolsHaveLowerDiscrepancyThanIndependent) {
    // L2 star discrepancy of N = 256 points averaged over 64 pixels, for the pixel pair and a
    // bounce's BSDF and light pairs. Random points have E[D²] = (1/4 − 1/9)/N, so D ≈ 0.023, with
    // a spread of the 64-pixel mean of a few percent; jittered and (0,2)-net points are several
    // times lower. Bound: half of independent's.
    for (uint dim : {SAMPLE_DIM_PIXEL, SAMPLE_DIM_LENS, sampleDim(0, SAMPLE_BOUNCE_BSDF), sampleDim(1, SAMPLE_BOUNCE_LIGHT)}) {
        const double independent = meanDiscrepancy(Kind::Independent, dim, 256, 64);
        EXPECT_NEAR(independent, std::sqrt((0.25 - 1.0 / 9.0) / 256.0), 0.003) << "dim " << dim;
        for (Kind kind : {Kind::Stratified, Kind::Sobol, Kind::ZSobol})
            EXPECT_LT(meanDiscrepancy(kind, dim, 256, 64), 0.5 * independent) << name(kind) << " dim " << dim;
    }
}

TEST(Sampler, SobolConvergesFasterThanMonteCarloOnASmoothIntegrand) {
    // ∫∫ e^x cos y over the unit square = (e − 1) sin 1, estimated with N = 4 … 1024 samples in
    // 256 pixels: independent's RMSE falls as N^−1/2 (the fitted slope's standard error is about
    // 0.02, so ±0.1 is five of them); stratified must be steeper than −0.8 and the sobols than
    // −1.2: they are near −1 and −1.5 (Owen 1997: O(N^−3/2) for smooth integrands).
    const auto f = [](vec2 u) { return std::exp(double(u.x)) * std::cos(double(u.y)); };
    const double exact = (std::exp(1.0) - 1.0) * std::sin(1.0);
    const std::vector<double> ns = {4, 16, 64, 256, 1024};
    for (Kind kind : kKinds) {
        std::vector<double> errors;
        for (double n : ns) errors.push_back(rmse(kind, sampleDim(0, SAMPLE_BOUNCE_BSDF), uint(n), 256, f, exact));
        const double slope = stats::logLogSlope(ns, errors);
        std::printf("%s: RMSE slope %.3f\n", name(kind), slope);
        if (kind == Kind::Independent) EXPECT_NEAR(slope, -0.5, 0.1);
        else EXPECT_LT(slope, kind == Kind::Stratified ? -0.8 : -1.2) << name(kind);
    }
}

namespace {

// The fraction of the power of a square image's error (mean removed) at radial frequencies
// 0 < |k| <= kmax cycles per image, by a separable DFT.
double lowFrequencyPowerFraction(const std::vector<double>& image, int size, int kmax) {
    double mean = 0.0;
    for (double v : image) mean += v;
    mean /= double(image.size());
    std::vector<std::complex<double>> f(image.size());
    for (size_t i = 0; i < image.size(); ++i) f[i] = image[i] - mean;
    auto dft = [&](int stride, int step) {   // along rows (stride 1) or columns (stride size)
        std::vector<std::complex<double>> line(size_t(size), 0.0);
        for (int l = 0; l < size; ++l) {
            for (int k = 0; k < size; ++k) {
                std::complex<double> sum = 0.0;
                for (int x = 0; x < size; ++x)
                    sum += f[size_t(l * step + x * stride)] * std::polar(1.0, -2.0 * M_PI * k * x / size);
                line[size_t(k)] = sum;
            }
            for (int k = 0; k < size; ++k) f[size_t(l * step + k * stride)] = line[size_t(k)];
        }
    };
    dft(1, size);
    dft(size, 1);
    double low = 0.0, all = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int kx = x <= size / 2 ? x : x - size, ky = y <= size / 2 ? y : y - size;
            const double p = std::norm(f[size_t(y * size + x)]);
            all += p;
            if (kx * kx + ky * ky <= kmax * kmax) low += p;
        }
    return low / all;
}

} // namespace

TEST(Sampler, ZSobolErrorAtOneSampleIsBlueNoiseAcrossTheScreen) {
    // A 64 × 64 image of one sample per pixel of a smooth integrand and of one with an edge, seed
    // fixed. White noise puts 196/4095 ≈ 4.8 % of its power at 0 < |k| <= 8 cycles per image: 98
    // conjugate pairs of exponentially distributed power, a relative spread of 10 %. The samplers
    // that scramble each pixel alone are white (within 4 spreads: 12 checks, p < 1e-3 together);
    // zsobol's Morton order moves the power to high frequencies: below half of white's, 5 spreads.
    const int size = 64;
    const std::function<double(vec2)> integrands[] = {
        [](vec2 u) { return std::exp(double(u.x)) * std::cos(double(u.y)); },
        [](vec2 u) { return u.x + u.y < 1.0f ? 1.0 : 0.0; }};
    for (const auto& f : integrands)
        for (uint dim : {SAMPLE_DIM_PIXEL, sampleDim(1, SAMPLE_BOUNCE_BSDF)}) {
            double fraction[4] = {};
            for (Kind kind : kKinds) {
                std::vector<double> image;
                for (int y = 0; y < size; ++y)
                    for (int x = 0; x < size; ++x) image.push_back(f(point2D(kind, uvec2(uint(x), uint(y)), 0u, dim, 17u, 1u)));
                fraction[int(kind)] = lowFrequencyPowerFraction(image, size, 8);
                std::printf("dim %u %s: %.4f of the power at |k| <= 8\n", dim, name(kind), fraction[int(kind)]);
            }
            const double white = 196.0 / 4095.0;
            for (Kind kind : {Kind::Independent, Kind::Stratified, Kind::Sobol})
                EXPECT_NEAR(fraction[int(kind)], white, 0.4 * white) << name(kind) << " dim " << dim;
            EXPECT_LT(fraction[int(Kind::ZSobol)], 0.5 * white) << "dim " << dim;
        }
}
