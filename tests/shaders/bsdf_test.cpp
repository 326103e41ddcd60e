// The shared BSDF code (shaders/include/bsdf.glsl and friends) run on the CPU: every sampler
// against its own pdf (χ²), sample / eval / pdf consistency, energy, the single-scattering
// albedo of GGX against our own quadrature, and no NaN anywhere.
#include "shaders/include/bsdf.glsl"
#include "shaders/include/frame.glsl"
#include "shaders/include/random.glsl"
#include "support/ggx_albedo.h"
#include "support/lobe_grid.h"
#include "support/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

using namespace raylab;
using namespace raylab::glsl;

namespace {

constexpr double kAlpha = 0.01;                           // family-wise significance
const float kAlphas[] = {0.01f, 0.05f, 0.2f, 0.5f, 1.0f};  // GGX α (the D-term width)
const float kCosines[] = {1.0f, 0.7f, 0.3f, 0.05f};        // incident cosθ

vec3 outgoing(float cosTheta) {
    const float s = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return vec3(s, 0.0f, cosTheta);
}

// A material from perceptual roughness's α directly (tests sweep α).
BsdfParams material(vec3 albedo, vec3 f0, float alpha, float transmission = 0.0f, float ior = 1.5f) {
    return BsdfParams(albedo, f0, std::max(alpha, GGX_MIN_ALPHA), transmission, ior);
}

struct SweepResult {
    test::ChiSquareResult chi;
    double pdfIntegral = 0.0;
    int inconsistent = 0;   // samples whose weight or pdf disagrees with eval / pdf
    int nonFinite = 0;
};

// Draws n samples from bsdfSample, histograms the non-delta ones and tests them against bsdfPdf.
SweepResult chiSquareOfBsdf(const BsdfParams& m, vec3 wo, float lobeWidth, int n, uint seed,
                            vec3 centre = vec3(0.0f)) {
    if (centre == vec3(0.0f)) centre = vec3(-wo.x, -wo.y, wo.z);   // the mirror direction
    const test::LobeGrid grid(glm::normalize(centre), std::max(2.0f * lobeWidth, 0.02f));
    std::vector<double> observed(size_t(grid.na * grid.nphi), 0.0);
    SweepResult r;
    Rng rng = rngCreate(uvec2(seed, 7), 0u, seed);
    for (int i = 0; i < n; ++i) {
        const vec2 u = rngNext2(rng);
        const BsdfSample s = bsdfSample(m, wo, vec3(u.x, u.y, rngNextFloat(rng)));
        if (!std::isfinite(s.weight.x + s.weight.y + s.weight.z + s.pdf + s.wi.x + s.wi.y + s.wi.z)) {
            ++r.nonFinite;
            continue;
        }
        if (s.lobe == LOBE_NONE || s.delta) continue;
        observed[size_t(grid.cell(s.wi))] += 1.0;
        const float pdf = bsdfPdf(m, wo, s.wi);
        const vec3 expect = bsdfEval(m, wo, s.wi) / pdf;
        const float tol = 2e-3f;
        if (std::abs(s.pdf - pdf) > tol * pdf ||
            glm::length(s.weight - expect) > tol * std::max(1.0f, glm::length(expect)))
            ++r.inconsistent;
    }
    const auto expected = grid.expected([&](vec3 w) { return double(bsdfPdf(m, wo, w)); }, double(n), observed);
    for (double e : expected) r.pdfIntegral += e / n;
    r.chi = test::chiSquareTest(observed, expected);
    return r;
}

} // namespace

// ctest: slow
TEST(ShaderBsdf, GgxVisibleNormalAndPlasticSamplersMatchTheirPdfAcrossTheSweep) {
    // Metal (F = 1, specular only) and plastic (f0 0.04 over albedo 0.5: both lobes), over the
    // α × cosθ sweep: 40 tests, Šidák-corrected α = 0.01, 10^6 samples each.
    const int tests = 2 * 5 * 4;
    const double perTest = test::sidak(kAlpha, tests);
    const int n = 1000000;
    uint seed = 1;
    for (int kind = 0; kind < 2; ++kind)
        for (float alpha : kAlphas)
            for (float mu : kCosines) {
                const BsdfParams m = kind == 0 ? material(vec3(0.0f), vec3(1.0f), alpha)
                                               : material(vec3(0.5f), vec3(0.04f), alpha);
                const SweepResult r = chiSquareOfBsdf(m, outgoing(mu), alpha, n, ++seed);
                SCOPED_TRACE((kind == 0 ? "metal" : "plastic") + std::string(" alpha ") + std::to_string(alpha) +
                             " cos " + std::to_string(mu));
                EXPECT_EQ(r.nonFinite, 0);
                EXPECT_EQ(r.inconsistent, 0);
                EXPECT_FALSE(r.chi.sampleInZeroCell);
                EXPECT_LE(r.pdfIntegral, 1.01);
                EXPECT_GT(r.chi.pValue, perTest) << "chi2 " << r.chi.statistic << " dof " << r.chi.dof;
            }
}

// ctest: slow
TEST(ShaderBsdf, RoughDielectricSamplerMatchesItsPdfAcrossTheSweep) {
    // Walter et al. 2007 glass (transmission 1) with visible normals: α × cosθ × IOR {1.5, 1/1.5}
    // (IOR 1/1.5 = leaving glass of index 1.5: wo inside). Cells centred on the smooth refraction
    // direction, or on the mirror direction under total internal reflection. 40 tests,
    // Šidák-corrected α = 0.01, 10^6 samples each; consistency of every sample as above.
    const double perTest = test::sidak(kAlpha, 40);
    const int n = 1000000;
    uint seed = 300;
    for (float ior : {1.5f, 1.0f / 1.5f})
        for (float alpha : kAlphas)
            for (float mu : kCosines) {
                // ior 1/1.5 is tested as glass of IOR 1.5 seen from inside.
                const bool inside = ior < 1.0f;
                const vec3 wo = outgoing(mu) * vec3(1.0f, 1.0f, inside ? -1.0f : 1.0f);
                const BsdfParams m = material(vec3(0.0f), vec3(0.0f), alpha, 1.0f, 1.5f);
                const vec3 centre = test::refractionLobeCentre(wo, ior);
                const SweepResult r = chiSquareOfBsdf(m, wo, alpha, n, ++seed, centre);
                SCOPED_TRACE("ior " + std::to_string(ior) + " alpha " + std::to_string(alpha) + " cos " +
                             std::to_string(mu));
                EXPECT_EQ(r.nonFinite, 0);
                EXPECT_EQ(r.inconsistent, 0);
                EXPECT_FALSE(r.chi.sampleInZeroCell);
                EXPECT_LE(r.pdfIntegral, 1.01);
                EXPECT_GT(r.chi.pValue, perTest) << "chi2 " << r.chi.statistic << " dof " << r.chi.dof;
            }
}

TEST(ShaderBsdf, ChiSquareRejectsAWrongPdf) {
    // The sweep must be able to fail: samples of α = 0.5 judged against the pdf of α = 0.55.
    const int n = 1000000;
    const vec3 wo = outgoing(0.7f);
    const BsdfParams sampled = material(vec3(0.0f), vec3(1.0f), 0.5f);
    const BsdfParams claimed = material(vec3(0.0f), vec3(1.0f), 0.55f);
    const test::LobeGrid grid(glm::normalize(vec3(-wo.x, -wo.y, wo.z)), 1.0f);
    std::vector<double> observed(size_t(grid.na * grid.nphi), 0.0);
    Rng rng = rngCreate(uvec2(1, 1), 0u, 3u);
    for (int i = 0; i < n; ++i) {
        const vec2 u = rngNext2(rng);
        const BsdfSample s = bsdfSample(sampled, wo, vec3(u.x, u.y, 0.5f));
        if (s.lobe != LOBE_NONE) observed[size_t(grid.cell(s.wi))] += 1.0;
    }
    const auto expected = grid.expected([&](vec3 w) { return double(bsdfPdf(claimed, wo, w)); }, double(n));
    EXPECT_LT(test::chiSquareTest(observed, expected).pValue, 1e-6);
}

TEST(ShaderBsdf, SmoothDielectricChoosesReflectionWithFresnelProbabilityAndObeysSnell) {
    // Two outcomes per configuration: χ² of the reflect / refract counts against N·F, N·(1 − F),
    // for IOR 1.5 and 1/1.5 entering and leaving. 16 tests, Šidák-corrected α = 0.01.
    const double perTest = test::sidak(kAlpha, 16);
    const int n = 1000000;
    uint seed = 100;
    for (float ior : {1.5f, 1.0f / 1.5f})
        for (float side : {1.0f, -1.0f})
            for (float mu : kCosines) {
                SCOPED_TRACE("ior " + std::to_string(ior) + " side " + std::to_string(side) + " cos " +
                             std::to_string(mu));
                const vec3 wo = outgoing(mu) * vec3(1.0f, 1.0f, side);
                const float eta = side > 0 ? ior : 1.0f / ior;
                const double F = fresnelDielectric(mu, eta);
                const BsdfParams m = material(vec3(0.0f), vec3(0.0f), 0.0f, 1.0f, ior);
                std::vector<double> observed(2, 0.0);
                Rng rng = rngCreate(uvec2(++seed, 1), 0u, 5u);
                for (int i = 0; i < n; ++i) {
                    const vec2 u = rngNext2(rng);
                    const BsdfSample s = bsdfSample(m, wo, vec3(u.x, u.y, rngNextFloat(rng)));
                    ASSERT_TRUE(s.delta);
                    if (s.lobe == LOBE_GLASS_REFLECT) {
                        observed[0] += 1;
                        ASSERT_NEAR(glm::length(s.wi - vec3(-wo.x, -wo.y, wo.z)), 0.0f, 1e-5f);
                        ASSERT_NEAR(s.pdf, float(F), 1e-5f);
                    } else {
                        ASSERT_EQ(s.lobe, LOBE_GLASS_TRANSMIT);
                        observed[1] += 1;
                        ASSERT_LT(s.wi.z * wo.z, 0.0f);   // crossed the surface
                        const float sinI = std::sqrt(1 - wo.z * wo.z);
                        const float sinT = std::sqrt(1 - s.wi.z * s.wi.z);
                        ASSERT_NEAR(sinT * eta, sinI, 1e-4f);   // Snell
                        ASSERT_NEAR(s.weight.x, 1.0f / (eta * eta), 1e-5f);
                        ASSERT_NEAR(s.wi.x * wo.x, -std::abs(s.wi.x * wo.x), 1e-7f);   // same plane, other side
                    }
                }
                if (F >= 1.0) {
                    EXPECT_EQ(observed[1], 0.0) << "total internal reflection";
                    continue;
                }
                const auto chi = test::chiSquareTest(observed, {n * F, n * (1 - F)}, 0.0);
                EXPECT_GT(chi.pValue, perTest) << "F " << F << " reflected " << observed[0];
            }
}

TEST(ShaderBsdf, EnergyNoMaterialReturnsMoreThanItReceives) {
    // Mean of f·|cos|/pdf over 16k samples ≤ 1.01 (pbrt-v4 BSDFEnergyConservation) for random wo.
    struct Case { const char* name; BsdfParams m; };
    const Case cases[] = {
        {"white lambert", material(vec3(1.0f), vec3(0.0f), 1.0f)},
        {"white plastic rough", material(vec3(1.0f), vec3(0.04f), 0.5f)},
        {"white plastic glossy", material(vec3(1.0f), vec3(0.04f), 0.05f)},
        {"white plastic mirror", material(vec3(1.0f), vec3(0.04f), 0.0f)},
        {"metal F=1 rough", material(vec3(0.0f), vec3(1.0f), 1.0f)},
        {"metal F=1 glossy", material(vec3(0.0f), vec3(1.0f), 0.01f)},
        {"gold", material(vec3(0.0f), vec3(1.0f, 0.71f, 0.29f), 0.2f)},
        {"mirror", material(vec3(0.0f), vec3(1.0f), 0.0f)},
        {"glass from outside", material(vec3(0.0f), vec3(0.0f), 0.0f, 1.0f, 1.5f)},
        {"half glass half plastic", material(vec3(1.0f), vec3(0.04f), 0.3f, 0.5f, 1.5f)},
        {"rough glass from outside", material(vec3(0.0f), vec3(0.0f), 0.3f, 1.0f, 1.5f)},
        {"rough glass, plastic mix", material(vec3(1.0f), vec3(0.04f), 0.05f, 0.5f, 1.5f)},
    };
    Rng rng = rngCreate(uvec2(9, 9), 0u, 9u);
    for (const Case& c : cases) {
        for (int k = 0; k < 16; ++k) {
            const float mu = std::max(rngNextFloat(rng), 1e-3f);
            const vec3 wo = outgoing(mu);
            vec3 sum(0.0f);
            const int n = 16384;
            for (int i = 0; i < n; ++i) {
                const vec2 u = rngNext2(rng);
                sum += bsdfSample(c.m, wo, vec3(u.x, u.y, rngNextFloat(rng))).weight;
            }
            const vec3 mean = sum / float(n);
            EXPECT_LE(maxComponent(mean), 1.01f) << c.name << " cos " << mu;
        }
    }
}

TEST(ShaderBsdf, GgxSingleScatteringAlbedoMatchesQuadratureWithinHalfAPercent) {
    // testing.md's table, measured elsewhere, is a cross-check of the quadrature (3 digits).
    struct Row { double alpha, e1, e05, e01; };
    const Row table[] = {{0.1, 0.988, 0.969, 0.883}, {0.3, 0.877, 0.822, 0.889},
                         {0.5, 0.688, 0.698, 0.860}, {1.0, 0.307, 0.451, 0.760}};
    for (const Row& row : table) {
        const double mus[] = {1.0, 0.5, 0.1};
        const double ref[] = {row.e1, row.e05, row.e01};
        for (int i = 0; i < 3; ++i) {
            SCOPED_TRACE("alpha " + std::to_string(row.alpha) + " mu " + std::to_string(mus[i]));
            const double e = test::ggxAlbedoQuadrature(mus[i], row.alpha);
            EXPECT_NEAR(e, ref[i], 0.006) << "quadrature vs table";
            // Monte Carlo with the shader's sampler: mean weight of 10^6 samples (F = 1, no diffuse).
            const BsdfParams m = material(vec3(0.0f), vec3(1.0f), float(row.alpha));
            const vec3 wo = outgoing(float(mus[i]));
            Rng rng = rngCreate(uvec2(i, 3), 0u, uint(row.alpha * 100));
            double sum = 0.0;
            const int n = 1000000;
            for (int s = 0; s < n; ++s) {
                const vec2 u = rngNext2(rng);
                sum += double(bsdfSample(m, wo, vec3(u.x, u.y, 0.5f)).weight.x);
            }
            EXPECT_NEAR(sum / n, e, 0.005 * e) << "Monte Carlo vs quadrature";
        }
    }
}

TEST(ShaderBsdf, NoNanForAxisNormalsGrazingRoughnessZeroAndIorOne) {
    const vec3 axes[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const BsdfParams mats[] = {
        material(vec3(0.8f), vec3(0.0f), 1.0f),   material(vec3(0.5f), vec3(0.04f), 0.0f),
        material(vec3(0.0f), vec3(1.0f), 0.0f),   material(vec3(0.0f), vec3(1.0f), 1e-4f),
        material(vec3(0.0f), vec3(1.0f), 1e-3f),   material(vec3(0.5f), vec3(0.04f), 1.0f),
        material(vec3(0.0f), vec3(0.0f), 0.0f, 1.0f, 1.0f),   // IOR 1
        material(vec3(0.0f), vec3(0.0f), 0.0f, 1.0f, 1.5f),
        material(vec3(0.2f), vec3(0.04f), 0.01f, 0.5f, 1.0f / 1.5f),
        material(vec3(0.0f), vec3(0.0f), 0.3f, 1.0f, 1.5f),    // rough glass
        material(vec3(0.0f), vec3(0.0f), 0.3f, 1.0f, 1.0f),    // rough glass, IOR 1
        material(vec3(0.0f), vec3(0.0f), 1.0f, 1.0f, 1.0f / 1.5f),
        material(vec3(0.5f), vec3(0.0f), 0.002f, 0.5f, 1.5f),
    };
    Rng rng = rngCreate(uvec2(5, 5), 0u, 5u);
    int checked = 0;
    for (vec3 n : axes) {
        const Frame f = frameFromNormal(n);
        // Directions: along the normal, exactly grazing, nearly grazing, from below, random.
        std::vector<vec3> dirs = {n, -n, f.t, -f.b, glm::normalize(f.t + 1e-7f * n), glm::normalize(f.b - 1e-6f * n)};
        for (int i = 0; i < 8; ++i) dirs.push_back(glm::normalize(vec3(rngNextFloat(rng) - 0.5f,
                                                                       rngNextFloat(rng) - 0.5f, rngNextFloat(rng) - 0.5f)));
        for (const BsdfParams& m : mats)
            for (vec3 d : dirs) {
                const vec3 wo = frameToLocal(f, d);
                for (int i = 0; i < 64; ++i) {
                    const vec2 u = rngNext2(rng);
                    const float uz = i == 0 ? 0.0f : (i == 1 ? 0.99999994f : rngNextFloat(rng));
                    const BsdfSample s = bsdfSample(m, wo, vec3(i == 2 ? 0.0f : u.x, u.y, uz));
                    const vec3 e = bsdfEval(m, wo, s.wi);
                    const float p = bsdfPdf(m, wo, s.wi);
                    const float all = s.weight.x + s.weight.y + s.weight.z + s.pdf + s.wi.x + s.wi.y + s.wi.z +
                                      e.x + e.y + e.z + p;
                    ASSERT_TRUE(std::isfinite(all)) << "normal " << n.x << "," << n.y << "," << n.z;
                    ASSERT_GE(s.pdf, 0.0f);
                    ASSERT_GE(std::min({s.weight.x, s.weight.y, s.weight.z}), 0.0f);
                    ++checked;
                }
            }
    }
    EXPECT_GT(checked, 0);
    // IOR 1: the glass part passes light straight through with weight 1.
    const BsdfSample s = bsdfSample(mats[6], vec3(0.6f, 0.0f, 0.8f), vec3(0.3f, 0.3f, 0.5f));
    EXPECT_EQ(s.lobe, LOBE_GLASS_TRANSMIT);
    EXPECT_NEAR(glm::length(s.wi - vec3(-0.6f, 0.0f, -0.8f)), 0.0f, 1e-6f);
    EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);
}

TEST(ShaderBsdf, PureLambertIsExactlyTheOldLambert) {
    // f0 = 0 switches the specular layer off: the weight is exactly the albedo and no lobe number
    // is needed, which keeps the furnace tests zero-variance and their random streams unchanged.
    const BsdfParams m = material(vec3(0.5f, 0.25f, 0.125f), vec3(0.0f), 1.0f);
    EXPECT_FALSE(bsdfNeedsLobeChoice(m));
    Rng rng = rngCreate(uvec2(2, 2), 0u, 2u);
    for (int i = 0; i < 1000; ++i) {
        const float mu = std::max(rngNextFloat(rng), 1e-4f);
        const BsdfSample s = bsdfSample(m, outgoing(mu), vec3(rngNext2(rng), 0.5f));
        ASSERT_EQ(s.weight, vec3(0.5f, 0.25f, 0.125f));
        ASSERT_EQ(s.lobe, LOBE_DIFFUSE);
    }
}

TEST(ShaderGgx, VisibleNormalSamplingBeatsDCosSamplingAtGrazingAngles) {
    // The variance of the F = 1 reflection estimator (weight f·cos/pdf) with VNDF sampling against
    // the classic D·cosθh sampling. Figures are printed for bench/materials.md.
    const float configs[][2] = {{0.2f, 0.05f}, {0.2f, 0.3f}, {0.5f, 0.05f}, {0.05f, 0.05f}, {0.2f, 1.0f}};
    for (const auto& cfg : configs) {
        const float alpha = cfg[0], mu = cfg[1];
        const vec3 wo = outgoing(mu);
        const BsdfParams m = material(vec3(0.0f), vec3(1.0f), alpha);
        const int n = 1000000;
        double s1[2] = {0, 0}, s2[2] = {0, 0}, maxW[2] = {0, 0};
        Rng rng = rngCreate(uvec2(1, 2), 0u, 77u);
        for (int i = 0; i < n; ++i) {
            const vec2 u = rngNext2(rng);
            // VNDF (the shader's sampler)
            const double wv = bsdfSample(m, wo, vec3(u.x, u.y, 0.5f)).weight.x;
            // D·cosθh: wi = reflect(wo, h), pdf = D cosθh / (4 wo·h)
            const vec3 h = ggxSampleDCos(alpha, u);
            double wd = 0.0;
            const float oh = glm::dot(wo, h);
            const vec3 wi = 2.0f * oh * h - wo;
            if (oh > 0.0f && wi.z > 0.0f) {
                const float pdf = ggxDCosPdf(h, alpha) / (4.0f * oh);
                if (pdf > 0.0f) wd = double(opaqueEval(m, wo, wi).x / pdf);
            }
            const double w[2] = {wv, wd};
            for (int k = 0; k < 2; ++k) {
                s1[k] += w[k];
                s2[k] += w[k] * w[k];
                maxW[k] = std::max(maxW[k], w[k]);
            }
        }
        double var[2], meanW[2];
        for (int k = 0; k < 2; ++k) {
            meanW[k] = s1[k] / n;
            var[k] = s2[k] / n - meanW[k] * meanW[k];
        }
        std::printf("alpha %.2f mu %.2f: mean VNDF %.4f DCos %.4f | variance VNDF %.3g DCos %.3g ratio %.1f | "
                    "max weight VNDF %.3g DCos %.3g\n",
                    double(alpha), double(mu), meanW[0], meanW[1], var[0], var[1], var[1] / var[0], maxW[0], maxW[1]);
        // Both estimate the same albedo (within 5 standard errors of the worse one)...
        EXPECT_NEAR(meanW[0], meanW[1], 5.0 * std::sqrt(var[1] / n) + 1e-4);
        // ...and VNDF weights are bounded by G2/G1 ≤ 1.
        EXPECT_LE(maxW[0], 1.0 + 1e-4);
        EXPECT_LE(var[0], var[1]);
    }
}
