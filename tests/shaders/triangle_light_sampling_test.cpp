// Emissive triangles as lights, sampled by the real GLSL on OSMesa (shaders/entry/bsdf_samples.comp):
// directions towards a triangle follow their solid-angle pdf, 1/Ω where the triangle subtends a
// solid angle Ω that triangle_light.glsl samples uniformly and dist² / (|cosθl| · area) where it
// takes a point by area (χ² on the sphere of directions), and the light alias table picks every
// light with probability proportional to its power (χ² on the picks).
#include "render/gpu_scene.h"
#include "scene/scene_loader.h"
#include "shaders/include/triangle_light.glsl"
#include "support/gl_test.h"
#include "support/gpu_sampler.h"
#include "support/lobe_grid.h"
#include "support/statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace raylab;

namespace {

class TriangleLightSamplingTest : public test::GlTest {};

// Solid-angle density of sampleTriangleLight for triangle (a, b, c) seen from the origin, in double:
// the ray along w meets the triangle (Möller–Trumbore, barycentrics within `slack` of it) at
// distance t; pdf = 1/Ω where triangleLightBySolidAngle takes Ω, else t² / (|cosθl| · area).
double trianglePdf(glm::dvec3 w, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, double slack = 0.0) {
    w = glm::normalize(w);
    const glm::dvec3 e1 = b - a, e2 = c - a, pv = glm::cross(w, e2);
    const double det = glm::dot(e1, pv);
    if (det == 0.0) return 0.0;
    const glm::dvec3 tv = -a;
    const double u = glm::dot(tv, pv) / det;
    const glm::dvec3 qv = glm::cross(tv, e1);
    const double v = glm::dot(w, qv) / det, t = glm::dot(e2, qv) / det;
    if (u < -slack || v < -slack || u + v > 1.0 + slack || t <= 0.0) return 0.0;
    const glm::dvec3 na = glm::normalize(a), nb = glm::normalize(b), nc = glm::normalize(c);
    const double omega = std::abs(2.0 * std::atan2(std::abs(glm::dot(na, glm::cross(nb, nc))),
                                                   1.0 + glm::dot(na, nb) + glm::dot(nb, nc) + glm::dot(nc, na)));
    if (glsl::triangleLightBySolidAngle(float(omega))) return 1.0 / omega;
    const glm::dvec3 n = glm::cross(e1, e2);
    const double area = 0.5 * glm::length(n);
    return t * t / (std::abs(glm::dot(glm::normalize(n), w)) * area);
}

double luminance(glm::vec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

} // namespace

TEST_F(TriangleLightSamplingTest, TriangleLightSamplesFromTheShaderFollowTheirPdf) {
    // Five triangles: tiny and far (Ω ≈ 10⁻⁵ sr: by area); small and far, facing the origin; large
    // and close (area sampling's pdf would vary by ~10× over it); seen at a grazing angle
    // (|cosθl| ≈ 0.04 at its centre), and one seen from its back (emission is two-sided); all but
    // the first by solid angle. 10^6 GPU samples each, cells of a lobe grid around the direction
    // of the centroid sized to the triangle; 5 tests, Šidák-corrected α = 0.01. Samples where the
    // pdf is 0 fail outright; each sample's pdf, and the pdf the shader gives a BSDF sample that
    // meets the same point (MIS), must match the CPU's double-precision pdf.
    struct Case { const char* name; glm::vec3 a, b, c; };
    const Case cases[] = {
        {"tiny", {-0.01f, 5.0f, -0.01f}, {0.01f, 5.0f, -0.01f}, {0.0f, 5.0f, 0.02f}},
        {"far", {-0.3f, 5.0f, -0.2f}, {0.3f, 5.0f, -0.2f}, {0.0f, 5.1f, 0.4f}},
        {"close", {-2.0f, 0.5f, -1.5f}, {2.5f, 0.5f, -1.0f}, {0.0f, 0.6f, 2.5f}},
        {"grazing", {-1.0f, 0.2f, 2.0f}, {1.0f, 0.2f, 2.0f}, {0.0f, 0.3f, 5.0f}},
        {"back", {0.0f, 1.2f, 2.5f}, {-1.0f, -2.0f, 2.0f}, {1.0f, -2.0f, 2.0f}},
    };
    const test::GpuSampler sampler;
    const unsigned n = 1000000;
    const double perTest = test::sidak(0.01, 5);
    unsigned seed = 300;
    for (const Case& k : cases) {
        SCOPED_TRACE(k.name);
        const glm::dvec3 a(k.a), b(k.b), c(k.c);
        const glm::vec3 centre = glm::normalize((k.a + k.b + k.c) / 3.0f);
        double maxAngle = 0.0;
        for (const glm::vec3& p : {k.a, k.b, k.c})
            maxAngle = std::max(maxAngle, std::acos(std::clamp(double(glm::dot(centre, glm::normalize(p))), -1.0, 1.0)));
        const test::LobeGrid grid(centre, float(std::tan(maxAngle / 2.0)));
        std::vector<double> observed(size_t(grid.na * grid.nphi), 0.0);
        int inconsistent = 0, offTriangle = 0, misInconsistent = 0;
        for (const auto& s : sampler.triangleLight(k.a, k.b, k.c, n, ++seed)) {
            ASSERT_TRUE(std::isfinite(s.pdf()) && s.pdf() > 0.0f);
            observed[size_t(grid.cell(s.wi()))] += 1.0;
            // Float rounding puts a direction by solid angle up to ~10⁻⁵ of an edge's length outside.
            const double pdf = trianglePdf(glm::dvec3(s.wi()), a, b, c, 1e-4);
            if (pdf == 0.0) ++offTriangle;
            else if (std::abs(s.pdf() - pdf) > 1e-3 * pdf) ++inconsistent;
            if (std::abs(s.weightLobe.x - s.pdf()) > 1e-3 * s.pdf()) ++misInconsistent;
        }
        EXPECT_EQ(inconsistent, 0);
        EXPECT_EQ(misInconsistent, 0) << "the pdf MIS gives a BSDF sample meeting the same point";
        EXPECT_EQ(offTriangle, 0) << "directions that miss the triangle by more than 10⁻⁴ in barycentrics";
        const auto expected = grid.expected([&](glm::vec3 w) { return trianglePdf(glm::dvec3(w), a, b, c); }, n, observed);
        const auto chi = test::chiSquareTest(observed, expected);
        EXPECT_FALSE(chi.sampleInZeroCell);
        EXPECT_GT(chi.pValue, perTest) << "chi2 " << chi.statistic << " dof " << chi.dof;
    }
}

TEST_F(TriangleLightSamplingTest, TheShaderPicksLightsInProportionToTheirPower) {
    // Three lamps (spheres) and an emissive mesh of triangles of different sizes, one of them
    // degenerate (no light), under a gradient sky; the scene's alias table is uploaded by GpuScene
    // and sampled by light_selection.glsl. Expected: the sky 1/2 when it is a light, the rest by
    // power (luminance × 4πr² for spheres, × 2·area for triangles, computed here). 10^6 picks,
    // with and without the sky: 2 tests, Šidák-corrected α = 0.01.
    const Scene scene = parseScene(R"({
      "sky": { "type": "gradient", "top": [0.3, 0.4, 0.6], "bottom": [0.2, 0.2, 0.2] },
      "materials": { "a": { "emission": [1, 0.5, 0.2], "strength": 4 }, "b": { "emission": 1, "strength": 1 },
                     "matte": { "albedo": 0.5 } },
      "objects": [
        { "type": "sphere", "center": [0, 0, 0], "radius": 0.3, "material": "a" },
        { "type": "sphere", "center": [3, 0, 0], "radius": 1.0, "material": "matte" },
        { "type": "sphere", "center": [0, 3, 0], "radius": 0.1, "material": "b" },
        { "type": "sphere", "center": [0, 0, 3], "radius": 0.6, "material": "b" },
        { "type": "mesh", "material": "a",
          "positions": [0,0,0, 1,0,0, 0,1,0, 3,0,0, 0,0.2,0, 7,7,7],
          "indices": [0, 1, 2, 0, 3, 4, 1, 1, 5, 0, 1, 4],
          "transform": { "translation": [0, 0, -3], "scale": [1, 2, 1] } }
      ] })", "selection.json");
    GpuScene gpu;
    gpu.upload(scene);
    gpu.bind();
    ASSERT_EQ(gpu.lightCount(), 3);
    ASSERT_EQ(gpu.triangleLightCount(), 3) << "the degenerate triangle is no light";
    // Powers: spheres in scene order; triangles as the shader sees them (world-space areas).
    const glm::vec3 La = glm::vec3(1, 0.5f, 0.2f) * 4.0f, Lb(1.0f);
    std::vector<double> power = {luminance(La) * 4 * M_PI * 0.09, luminance(Lb) * 4 * M_PI * 0.01,
                                 luminance(Lb) * 4 * M_PI * 0.36};
    // The three triangles' world areas (scale y by 2): 1, 0.6 and 0.2 (in BVH leaf order, which
    // the list follows; compare as a multiset by sorting both).
    std::vector<double> triangleExpected = {luminance(La) * 2 * 1.0, luminance(La) * 2 * 0.6, luminance(La) * 2 * 0.2};
    const auto& hostPower = gpu.lightPower();
    ASSERT_EQ(hostPower.size(), 6u);
    std::vector<double> triangleHost(hostPower.begin() + 3, hostPower.end());
    std::sort(triangleHost.begin(), triangleHost.end());
    std::sort(triangleExpected.begin(), triangleExpected.end());
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(triangleHost[size_t(i)], triangleExpected[size_t(i)], 1e-5);
    power.insert(power.end(), hostPower.begin() + 3, hostPower.end());   // in the list's order
    double total = 0.0;
    for (double p : power) total += p;

    const test::GpuSampler sampler;
    const unsigned n = 1000000;
    unsigned seed = 600;
    for (bool sky : {true, false}) {
        SCOPED_TRACE(sky ? "with the sky" : "without the sky");
        const double pSky = sky ? 0.5 : 0.0;
        std::vector<double> observed(7, 0.0), expected(7, 0.0);
        expected[6] = n * pSky;
        for (size_t i = 0; i < 6; ++i) expected[i] = n * (1.0 - pSky) * power[i] / total;
        // The number that made the pick comes back rescaled for the point on the light: uniform in
        // [0, 1) and independent of the pick, so within each light it is a fresh uniform number.
        constexpr size_t kBins = 8;
        std::vector<double> rescaled(7 * kBins, 0.0);
        int wrongPmf = 0, outside = 0;
        for (const auto& s : sampler.lightSelection(3, 3, sky, n, ++seed)) {
            const int k = int(s.wiPdf.x);
            ASSERT_GE(k, -1);
            ASSERT_LT(k, 6);
            const size_t cell = k < 0 ? 6 : size_t(k);
            observed[cell] += 1.0;
            if (std::abs(s.wiPdf.y - expected[cell] / n) > 1e-6 * std::max(1.0, expected[cell] / n)) ++wrongPmf;
            const float u = s.wiPdf.w;
            if (!(u >= 0.0f && u < 1.0f)) {
                ++outside;
                continue;
            }
            rescaled[cell * kBins + size_t(u * float(kBins))] += 1.0;
        }
        EXPECT_EQ(wrongPmf, 0) << "the pmf the shader reports for its pick";
        EXPECT_EQ(outside, 0) << "rescaled numbers outside [0, 1)";
        std::vector<double> rescaledExpected(7 * kBins);
        for (size_t i = 0; i < rescaledExpected.size(); ++i) rescaledExpected[i] = observed[i / kBins] / kBins;
        const auto chiU = test::chiSquareTest(rescaled, rescaledExpected, 0.0);
        EXPECT_GT(chiU.pValue, test::sidak(0.01, 2)) << "rescaled number: chi2 " << chiU.statistic << " dof " << chiU.dof;
        const auto chi = test::chiSquareTest(observed, expected, 0.0);
        EXPECT_FALSE(chi.sampleInZeroCell);
        EXPECT_GT(chi.pValue, test::sidak(0.01, 2)) << "chi2 " << chi.statistic << " dof " << chi.dof;
        // The test can fail: uniform picking is rejected.
        std::vector<double> uniform(7, n * (1.0 - pSky) / 6.0);
        uniform[6] = n * pSky;
        EXPECT_LT(test::chiSquareTest(observed, uniform, 0.0).pValue, 1e-6);
    }
}
