// The BRDF explorer's model without a window: the disk map, the polar curve and heat map against
// closed forms, and the χ² verdict on the real GLSL sampler (right material: pass; samples of one
// material judged against another's pdf: fail). Significance 0.01 per verdict, fixed seeds.
#include "inspect/brdf_explorer.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <numbers>

namespace raylab::test {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

Material lambert(glm::vec3 albedo) {
    Material m;
    m.albedo = albedo;
    return m;
}

Material material(glm::vec3 albedo, glm::vec3 f0, float roughness, float transmission = 0.0f) {
    Material m;
    m.albedo = albedo;
    m.f0 = f0;
    m.roughness = roughness;
    m.transmission = transmission;
    return m;
}

TEST(BrdfExplorer, DiskMapIsAnInvertibleEqualAreaMap) {
    for (float x = -0.95f; x <= 0.95f; x += 0.1f)
        for (float y = -0.95f; y <= 0.95f; y += 0.1f) {
            const glm::vec2 p(x, y);
            if (glm::dot(p, p) > 1.0f) continue;
            for (bool lower : {false, true}) {
                const glm::vec3 w = diskToDirection(p, lower);
                EXPECT_NEAR(glm::length(w), 1.0f, 1e-5f);
                EXPECT_EQ(w.z < 0.0f, lower && glm::dot(p, p) < 1.0f);
                const glm::vec2 q = directionToDisk(w);
                EXPECT_NEAR(q.x, p.x, 1e-4f);
                EXPECT_NEAR(q.y, p.y, 1e-4f);
            }
        }
    // Equal area: the disk of radius r holds the cap cosθ ≥ 1 − r², solid angle 2π r² = 2 × area.
    const glm::vec3 w = diskToDirection(glm::vec2(0.6f, 0.0f), false);
    EXPECT_NEAR(w.z, 1.0f - 0.36f, 1e-6f);
}

TEST(BrdfExplorer, LobeTogglesSwitchTheMaterialsParts) {
    Material m;
    m.albedo = glm::vec3(0.5f);
    m.f0 = glm::vec3(0.04f);
    m.transmission = 0.5f;
    m.roughness = 0.5f;
    const auto all = explorerBsdf(m);
    EXPECT_EQ(all.alpha, 0.25f);
    EXPECT_EQ(explorerBsdf(m, {false, true, true}).albedo, glm::vec3(0.0f));
    EXPECT_EQ(explorerBsdf(m, {true, false, true}).f0, glm::vec3(0.0f));
    EXPECT_EQ(explorerBsdf(m, {true, true, false}).transmission, 0.0f);
}

// The explorer shows the BSDF the tracer renders: an untextured metallic material is baked into f0
// and albedo as the scene upload does it (render/gpu_scene.cpp), f0 = mix(f0, base, m), albedo·(1 − m).
TEST(BrdfExplorer, MetallicIsBakedAsTheTracerBakesIt) {
    Material m;
    m.albedo = glm::vec3(0.9f, 0.5f, 0.1f);
    m.f0 = glm::vec3(0.04f);
    m.metallic = 0.75f;
    const auto p = explorerBsdf(m);
    EXPECT_NEAR(p.albedo.r, 0.9f * 0.25f, 1e-6f);
    EXPECT_NEAR(p.albedo.b, 0.1f * 0.25f, 1e-6f);
    EXPECT_NEAR(p.f0.r, 0.04f + 0.75f * (0.9f - 0.04f), 1e-6f);
    EXPECT_NEAR(p.f0.g, 0.04f + 0.75f * (0.5f - 0.04f), 1e-6f);
}

// The expected counts integrate the pdf over each cell; a narrow lobe at a grazing angle covers a
// few of the fixed sub-cells, so its integral must not depend on how coarse the cells are.
TEST(BrdfExplorer, ExpectedCountsIntegrateANarrowGrazingLobeAtAnyCellSize) {
    Material m;
    m.albedo = glm::vec3(0.0f);
    m.f0 = glm::vec3(0.9f);
    m.roughness = 0.1f;
    const auto p = explorerBsdf(m);
    const glm::vec3 wo = directionFromAngles(70.0f, 0.0f);
    const std::vector<GpuSample> one{{glm::vec4(0.0f, 0.0f, 1.0f, 1.0f), glm::vec4(1.0f, 1.0f, 1.0f, 2.0f)}};
    const double fine = testSampler(p, wo, one, 64).pdfIntegral;
    EXPECT_GT(fine, 0.99);
    for (int n : {4, 8, 16, 32}) EXPECT_NEAR(testSampler(p, wo, one, n).pdfIntegral, fine, 1e-3) << n << " cells";
}

TEST(BrdfExplorer, PolarCurveAndHeatMapOfLambertAreRhoCosOverPi) {
    const auto p = explorerBsdf(lambert(glm::vec3(0.6f)));
    const glm::vec3 wo = directionFromAngles(30.0f, 40.0f);
    for (const PolarPoint& q : polarCurve(p, wo, 72)) {
        const float c = std::cos(glm::radians(q.angleDeg));
        const float expected = std::abs(q.angleDeg) < 90.0f ? 0.6f / kPi * c : 0.0f;
        EXPECT_NEAR(q.fCos.x, expected, 1e-6f) << q.angleDeg;
    }
    const HemisphereMap map = hemisphereMap(p, wo, 9);
    EXPECT_NEAR(map.upper[4 * 9 + 4], 0.6f / kPi, 1e-3f);   // the centre cell: straight up
    EXPECT_EQ(map.upper[0], -1.0f);                           // a corner outside the disk
    EXPECT_EQ(map.lower[4 * 9 + 4], 0.0f);                    // nothing below an opaque surface
    EXPECT_NEAR(map.maxValue, 0.6f / kPi, 1e-3f);
    const HemisphereMap pdf = hemisphereMap(p, wo, 9, MapQuantity::Pdf);
    EXPECT_NEAR(pdf.upper[4 * 9 + 4], 1.0f / kPi, 1e-3f);   // cosine-weighted: cosθ/π
}

TEST(BrdfExplorer, PolarCurvePutsTheGgxPeakAtTheMirrorDirection) {
    Material m;
    m.albedo = glm::vec3(0.0f);
    m.f0 = glm::vec3(0.9f);
    m.roughness = 0.2f;
    const auto curve = polarCurve(explorerBsdf(m), directionFromAngles(50.0f, 0.0f), 360);
    const auto peak = std::max_element(curve.begin(), curve.end(),
                                       [](const PolarPoint& a, const PolarPoint& b) { return a.fCos.x < b.fCos.x; });
    EXPECT_NEAR(peak->angleDeg, 50.0f, 5.0f);   // off-specular peaks lean a little to grazing
}

using BrdfExplorerGpu = GlTest;

TEST_F(BrdfExplorerGpu, ChiSquareVerdictPassesTheRealSamplerAndFailsAWrongPdf) {
    GpuSampler sampler;
    struct Case {
        const char* name;
        Material m;
        float theta;
    };
    const Material ggx = material(glm::vec3(0.5f), glm::vec3(0.04f), 0.5f);
    const Material glass = material(glm::vec3(0.0f), glm::vec3(0.0f), 0.5f, 1.0f);
    const Material smoothGlassOverDiffuse = material(glm::vec3(0.7f), glm::vec3(0.0f), 0.0f, 0.4f);
    const std::vector<Case> cases = {{"lambert", lambert(glm::vec3(0.8f)), 20.0f},
                                     {"ggx+diffuse", ggx, 60.0f},
                                     {"rough glass", glass, 35.0f},
                                     {"smooth glass over diffuse", smoothGlassOverDiffuse, 45.0f}};
    for (const Case& c : cases) {
        const auto p = explorerBsdf(c.m);
        const glm::vec3 wo = directionFromAngles(c.theta, 10.0f);
        const auto samples = sampler.bsdf(p, wo, 40000, 11);
        const SamplerTest t = testSampler(p, wo, samples, 16, 0.01);
        EXPECT_TRUE(t.pass) << c.name << ": chi2 " << t.chi2.statistic << " dof " << t.chi2.dof << " p " << t.chi2.pValue
                            << " integral " << t.pdfIntegral;
        EXPECT_LT(t.maxPdfMismatch, 1e-3) << c.name;
        EXPECT_EQ(t.samples, 40000);
    }
    // Samples of a rough GGX judged against a smoother one's pdf: the verdict must be FAIL.
    Material rough = ggx, smooth = ggx;
    rough.roughness = 0.7f;
    smooth.roughness = 0.4f;
    const glm::vec3 wo = directionFromAngles(40.0f, 0.0f);
    const auto samples = sampler.bsdf(explorerBsdf(rough), wo, 40000, 5);
    const SamplerTest wrong = testSampler(explorerBsdf(smooth), wo, samples, 16, 0.01);
    EXPECT_FALSE(wrong.pass) << "p " << wrong.chi2.pValue;
    // Switching the diffuse lobe off changes the sampler and the pdf together: still a pass.
    const auto specOnly = explorerBsdf(ggx, {false, true, true});
    const SamplerTest spec = testSampler(specOnly, wo, sampler.bsdf(specOnly, wo, 40000, 6), 16, 0.01);
    EXPECT_TRUE(spec.pass) << "p " << spec.chi2.pValue << " integral " << spec.pdfIntegral;
}

// render.ggx_sampling d_cos and render.diffuse_sampling uniform: the GPU sampler and the pdf that
// eval and MIS use agree (χ² at 0.01 per verdict), for the specular lobe, rough glass (inside and
// out) and a grazing view, where D·cos draws many normals facing away; a d_cos sampler judged by
// the visible normals' pdf must fail.
TEST_F(BrdfExplorerGpu, ChiSquareVerdictPassesTheNaiveSamplers) {
    GpuSampler sampler;
    RenderSettings naive;
    naive.ggxSampling = GgxSampling::DCos;
    naive.diffuseSampling = DiffuseSampling::Uniform;
    const Material ggx = material(glm::vec3(0.5f), glm::vec3(0.04f), 0.5f);
    const Material metal = material(glm::vec3(0.0f), glm::vec3(0.9f), 0.6f);
    const Material glass = material(glm::vec3(0.0f), glm::vec3(0.0f), 0.5f, 1.0f);
    const struct {
        const char* name;
        Material m;
        float theta;
    } cases[] = {{"lambert", lambert(glm::vec3(0.8f)), 20.0f}, {"ggx+diffuse", ggx, 60.0f}, {"metal grazing", metal, 80.0f},
                 {"rough glass", glass, 35.0f}, {"rough glass inside", glass, 140.0f}};
    for (const auto& c : cases) {
        const auto p = explorerBsdf(c.m, {}, naive);
        EXPECT_EQ(p.ggxSampling, RAYLAB_GGX_D_COS);
        const glm::vec3 wo = directionFromAngles(c.theta, 10.0f);
        const SamplerTest t = testSampler(p, wo, sampler.bsdf(p, wo, 40000, 13), 16, 0.01);
        EXPECT_TRUE(t.pass) << c.name << ": chi2 " << t.chi2.statistic << " dof " << t.chi2.dof << " p " << t.chi2.pValue
                            << " integral " << t.pdfIntegral;
        EXPECT_LT(t.maxPdfMismatch, 1e-3) << c.name;
    }
    const glm::vec3 wo = directionFromAngles(70.0f, 0.0f);
    const auto dcos = explorerBsdf(metal, {}, naive);
    const SamplerTest wrong = testSampler(explorerBsdf(metal), wo, sampler.bsdf(dcos, wo, 40000, 14), 16, 0.01);
    EXPECT_FALSE(wrong.pass) << "p " << wrong.chi2.pValue;
}

} // namespace
} // namespace raylab::test
