// render.stage: the renderer built up stage by stage (scene.h RenderStage). Each stage is its own
// variant and must equal what it claims to be, on the same seed: primary = the albedo view,
// emission = max_bounces 0, lambert = the scene with f0 and transmission zeroed, ggx = the full
// tracer without textures, textures = the full tracer with a pinhole camera.
#include "render/debug_buffers.h"
#include "render/shader_variant.h"
#include "render/tracer_variants.h"
#include "render_helpers.h"
#include "support/gl_test.h"

#include <algorithm>
#include <cmath>

using namespace raylab;

namespace {

Scene small(const std::string& file, int spp = 4) {
    Scene s = loadScene(test::scenePath(file));
    s.render.width = 64;
    s.render.height = 36;
    s.render.spp = spp;
    s.render.rpp = 1;
    return s;
}

Scene staged(Scene s, RenderStage stage) {
    s.render.stage = stage;
    return s;
}

// Largest difference of any channel, relative to max(1e-3, |b|): float rounding only when equal.
double worstRelative(const Image& a, const Image& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        worst = std::max(worst, std::abs(double(a.rgba[i]) - b.rgba[i]) / std::max(1e-3, double(std::abs(b.rgba[i]))));
    }
    return worst;
}

double meanAbsDifference(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        if (i % 4 != 3) sum += std::abs(double(a.rgba[i]) - b.rgba[i]);
    return sum / double(a.rgba.size() / 4 * 3);
}

class RenderStageTest : public test::GlTest {};

} // namespace

TEST(RenderStage, EachStageLeavesLaterFeaturesOutOfTheVariant) {
    const Scene s = small("textured_bricks.json");
    ASSERT_TRUE(sceneFeatures(s).textures);
    EXPECT_FALSE(sceneFeatures(staged(s, RenderStage::Ggx)).textures);
    EXPECT_TRUE(sceneFeatures(staged(s, RenderStage::Textures)).textures);
    const Scene m = small("materials.json");
    ASSERT_TRUE(sceneFeatures(m).generalBsdf);
    EXPECT_FALSE(sceneFeatures(staged(m, RenderStage::Lambert)).generalBsdf);
    EXPECT_TRUE(sceneFeatures(staged(m, RenderStage::Ggx)).generalBsdf);
    Scene lens = m;
    lens.camera.aperture = 0.1f;
    EXPECT_FALSE(sceneFeatures(staged(lens, RenderStage::Textures)).depthOfField);
    EXPECT_TRUE(sceneFeatures(lens).depthOfField);
    EXPECT_NE(featureName(sceneFeatures(staged(m, RenderStage::Primary))).find("stage-primary"), std::string::npos);
    EXPECT_EQ(featureName(sceneFeatures(m)).find("stage"), std::string::npos) << "full is the plain tracer";
}

TEST(RenderStage, IsASceneKeyWithNamedStages) {
    const Scene s = loadScene(test::scenePath("default.json"), {"render.stage=lambert"});
    EXPECT_EQ(s.render.stage, RenderStage::Lambert);
    EXPECT_EQ(loadScene(test::scenePath("default.json")).render.stage, RenderStage::Full);
    EXPECT_THROW(loadScene(test::scenePath("default.json"), {"render.stage=phong"}), SceneError);
}

TEST_F(RenderStageTest, PrimaryIsTheAlbedoView) {
    const Scene s = small("materials.json");
    const Image primary = test::render(staged(s, RenderStage::Primary));
    PathTracer tracer(variantOptions(TracerVariant::Views, TracerEntry::Fragment));
    tracer.setScene(s);
    setTracedView(tracer.program(), DebugView::Albedo, 0);
    renderProgressively(tracer, s.render);
    const Image albedo = tracer.readImage();
    EXPECT_LT(worstRelative(primary, albedo), 1e-6);
    EXPECT_GT(meanAbsDifference(primary, test::render(s)), 0.01)
        << "the full tracer shows lighting, not albedo";
}

TEST_F(RenderStageTest, EmissionIsWhatTheCameraSeesDirectly) {
    Scene s = small("cornell_box.json");
    const Image emission = test::render(staged(s, RenderStage::Emission));
    s.render.maxBounces = 0;
    EXPECT_LT(worstRelative(emission, test::render(s)), 1e-6);
}

TEST_F(RenderStageTest, WithoutGgxTheHighlightsVanish) {
    const Scene s = small("materials.json", 8);
    const Image lambert = test::render(staged(s, RenderStage::Lambert));
    const Image ggx = test::render(staged(s, RenderStage::Ggx));
    // Lambert stage = the same scene with every material made Lambertian.
    Scene plain = s;
    for (Material& m : plain.materials) {
        m.f0 = glm::vec3(0.0f);
        m.transmission = 0.0f;
    }
    EXPECT_LT(worstRelative(lambert, test::render(plain)), 1e-5);
    // GGX stage = the full tracer (the scene has no textures and no lens).
    EXPECT_LT(worstRelative(ggx, test::render(s)), 1e-6);
    // The highlights vanish: the metals and the glass (albedo 0) are black without GGX, where the
    // full tracer shows their reflections; nothing that GGX leaves black is lit by Lambert alone
    // except through those materials' lost light.
    int blackWithoutGgx = 0, blackWithGgx = 0;
    for (int y = 0; y < ggx.height; ++y)
        for (int x = 0; x < ggx.width; ++x) {
            const float g = glm::dot(ggx.rgb(x, y), glm::vec3(1.0f / 3.0f));
            const float l = glm::dot(lambert.rgb(x, y), glm::vec3(1.0f / 3.0f));
            blackWithoutGgx += l == 0.0f && g > 0.05f;
            blackWithGgx += g == 0.0f && l > 0.05f;
        }
    EXPECT_GT(blackWithoutGgx, ggx.width * ggx.height / 20);
    EXPECT_EQ(blackWithGgx, 0);
}

TEST_F(RenderStageTest, TexturesStageAddsTheTexturesAndFullAddsTheLens) {
    const Scene s = small("textured_bricks.json");
    Scene untextured = s;
    for (Material& m : untextured.materials) {
        m.albedoTexture.clear();
        m.albedoTextureIndex = -1;
        m.normalTexture.clear();
        m.normalTextureIndex = -1;
    }
    untextured.textures.clear();
    const Image ggx = test::render(staged(s, RenderStage::Ggx));
    const Image textures = test::render(staged(s, RenderStage::Textures));
    EXPECT_LT(worstRelative(ggx, test::render(untextured)), 1e-6);
    EXPECT_GT(meanAbsDifference(ggx, textures), 0.01);

    Scene lens = small("depth_of_field.json");
    ASSERT_GT(lens.camera.aperture, 0.0f);
    const Image pinhole = test::render(staged(lens, RenderStage::Textures));
    const Image full = test::render(lens);
    lens.camera.aperture = 0.0f;
    EXPECT_LT(worstRelative(pinhole, test::render(lens)), 1e-6);
    EXPECT_GT(meanAbsDifference(pinhole, full), 0.005);
}
