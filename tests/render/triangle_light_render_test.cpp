// Emissive triangles as lights on the GPU (OSMesa): NEE-only, BSDF-only and MIS renders of the
// Cornell box and of a two-sided, transformed triangle lamp agree per pixel, and so do light
// samples by area and by solid angle; MIS beats BSDF-only, and solid angle beats area near a large
// lamp, at equal samples; scenes without emissive triangles compile the same variant as before.
#include "render/light_list.h"
#include "render/shader_variant.h"
#include "render_helpers.h"
#include "support/batch_stats.h"
#include "support/gl_test.h"
#include "support/statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

using namespace raylab;
using test::BatchStats;
using test::fractionAgreeing;
using test::renderBatches;

namespace {

class TriangleLightRenderTest : public test::GlTest {};

Scene cornell(std::vector<std::string> overrides) {
    overrides.insert(overrides.begin(), {"render.width=16", "render.height=16", "render.rpp=32", "render.spp=64",
                                         "render.max_bounces=4", "render.rr_depth=2"});
    return loadScene(test::scenePath("cornell_box.json"), overrides);
}

// A matte floor lit by a triangle lamp that stands upright, rotated and scaled by its transform,
// so both of its faces light the floor (emission is two-sided); a glossy sphere and a small
// emissive sphere beside it, so light selection mixes spheres and triangles of unequal power.
const char* kLampScene = R"({
  "camera": { "position": [0, 3, 4], "look_at": [0, 0.4, 0], "fov": 45 },
  "render": { "width": 16, "height": 12, "rpp": 32, "spp": 64, "max_bounces": 3, "rr_depth": 2 },
  "sky": { "type": "constant", "color": 0 },
  "materials": {
    "floor": { "albedo": 0.6 },
    "gloss": { "albedo": 0.2, "f0": 0.5, "roughness": 0.4 },
    "lamp": { "albedo": 0, "emission": [1, 0.8, 0.6], "strength": 4 },
    "bulb": { "albedo": 0, "emission": [0.6, 0.8, 1], "strength": 3 }
  },
  "objects": [
    { "type": "mesh", "material": "floor", "positions": [-4,0,-4, 4,0,-4, 4,0,4, -4,0,4], "indices": [0,2,1, 0,3,2] },
    { "type": "mesh", "material": "lamp", "positions": [-0.5,0,0, 0.5,0,0, 0.5,1,0, -0.5,1,0], "indices": [0,1,2, 0,2,3],
      "transform": { "translation": [0.2, 0.3, -0.3], "rotation": [0, 35, 0], "scale": [1.5, 0.8, 1] } },
    { "type": "sphere", "center": [-1.3, 0.5, 0.4], "radius": 0.5, "material": "gloss" },
    { "type": "sphere", "center": [1.4, 1.3, 0.6], "radius": 0.3, "material": "bulb" }
  ]
})";

Scene lampScene(std::vector<std::string> overrides) { return parseScene(kLampScene, "lamp.json", overrides); }

} // namespace

// 32 batches (seeds) of each strategy. NEE-only against MIS: per-pixel z-test at α = 0.01 (Šidák
// over pixels and channels), ≥ 99.5% of pixels must agree, as for the sphere scenes. BSDF-only
// finds these small lights by chance (the Cornell light covers ~1% of a bounce's directions), so
// its per-pixel batch means are far from normal (most batches 0 or one hit in dim pixels) and a
// per-pixel z-test would reject a correct estimator; it is compared on 4 × 4 pixel blocks
// (z-test at α = 0.01, Šidák over blocks and channels), every block must agree.
// ctest: slow
TEST_F(TriangleLightRenderTest, CornellBoxNeeBsdfAndMisAgree) {
    constexpr int batches = 32;
    const BatchStats bsdf = renderBatches(cornell({"render.nee=false"}), batches);
    const BatchStats nee = renderBatches(cornell({"render.nee=true", "render.mis=false"}), batches);
    const BatchStats mis = renderBatches(cornell({"render.nee=true", "render.mis=true"}), batches);
    EXPECT_GE(fractionAgreeing(mis, nee), 0.995);
    EXPECT_EQ(test::fractionOfBlocksAgreeing(mis, bsdf, 16, 4), 1.0);
    EXPECT_EQ(test::fractionOfBlocksAgreeing(nee, bsdf, 16, 4), 1.0);
    // The test can fail: 20% more light must be seen, per pixel and per block.
    const BatchStats brighter = renderBatches(cornell({"render.nee=true", "materials.light.strength=1.2"}), batches);
    EXPECT_LT(fractionAgreeing(mis, brighter), 0.9);
    EXPECT_LT(test::fractionOfBlocksAgreeing(bsdf, brighter, 16, 4), 0.75);
}

TEST_F(TriangleLightRenderTest, TwoSidedTransformedTriangleLampAgreesAcrossStrategies) {
    constexpr int batches = 32;
    const BatchStats bsdf = renderBatches(lampScene({"render.nee=false"}), batches);
    const BatchStats nee = renderBatches(lampScene({"render.nee=true", "render.mis=false"}), batches);
    const BatchStats mis = renderBatches(lampScene({"render.nee=true", "render.mis=true"}), batches);
    EXPECT_GE(fractionAgreeing(mis, nee), 0.995);
    EXPECT_EQ(test::fractionOfBlocksAgreeing(mis, bsdf, 16, 4), 1.0);
    EXPECT_EQ(test::fractionOfBlocksAgreeing(nee, bsdf, 16, 4), 1.0);
    // The test can fail: the lamp lit on one face only (NEE of a one-sided lamp) must be seen;
    // here, a lamp 20% dimmer.
    const BatchStats dimmer = renderBatches(lampScene({"render.nee=true", "materials.lamp.strength=3.2"}), batches);
    EXPECT_LT(test::fractionOfBlocksAgreeing(bsdf, dimmer, 16, 4), 0.75);
}

// render.light_sampling area against the default solid_angle, on the lamp that stands on the floor
// (much of the floor sees it under a large solid angle): NEE-only of each, and MIS by area, agree
// with NEE-only by solid angle per pixel (as above, ≥ 99.5 % of pixels at α = 0.01, Šidák).
TEST_F(TriangleLightRenderTest, LightSamplingByAreaAndBySolidAngleAgree) {
    constexpr int batches = 32;
    const BatchStats solidAngle = renderBatches(lampScene({"render.mis=false"}), batches);
    const BatchStats area = renderBatches(lampScene({"render.mis=false", "render.light_sampling=area"}), batches);
    const BatchStats areaMis = renderBatches(lampScene({"render.light_sampling=area"}), batches);
    EXPECT_GE(fractionAgreeing(area, solidAngle), 0.995);
    EXPECT_GE(fractionAgreeing(areaMis, solidAngle), 0.995);
    // The test can fail: a lamp 10% dimmer must be seen.
    const BatchStats dimmer = renderBatches(lampScene({"render.mis=false", "materials.lamp.strength=3.6"}), batches);
    EXPECT_LT(fractionAgreeing(area, dimmer), 0.9);
}

// Near a large lamp, a light sample by solid angle has the 1/r² and the light's cosine out of its
// weight: at equal samples (16, NEE only, 64×48 of the standing lamp) its RMSE against a 1024-spp
// reference (another seed) is below area sampling's. Measured 0.0202 against 0.0243 (−17 %); the
// bound asks for 10 %.
TEST_F(TriangleLightRenderTest, LightSamplingBySolidAngleHasLowerErrorNearALargeLamp) {
    auto with = [](std::vector<std::string> more) {
        more.insert(more.begin(), {"render.width=64", "render.height=48", "render.rpp=16", "render.mis=false"});
        return lampScene(more);
    };
    const Image reference = test::render(with({"render.spp=1024", "render.rpp=64", "render.seed=99"}));
    const double solidAngle = test::rmse(test::render(with({"render.spp=16"})), reference);
    const double area = test::rmse(test::render(with({"render.spp=16", "render.light_sampling=area"})), reference);
    std::printf("standing lamp 64x48, 16 spp NEE only, RMSE vs 1024 spp: by solid angle %.4f, by area %.4f\n",
                solidAngle, area);
    EXPECT_LT(solidAngle, 0.9 * area);
}

// ctest: slow
TEST_F(TriangleLightRenderTest, MisHasLowerErrorThanBsdfSamplingOnTheCornellBox) {
    // Equal samples per pixel (16), 32×32; the reference is MIS at 1024 spp (another seed).
    auto with = [](std::vector<std::string> more) {
        more.insert(more.begin(), {"render.width=32", "render.height=32", "render.rpp=16"});
        return loadScene(test::scenePath("cornell_box.json"), more);
    };
    const Image reference = test::render(with({"render.spp=1024", "render.rpp=64", "render.seed=99", "render.nee=true"}));
    const double bsdf = test::rmse(test::render(with({"render.spp=16", "render.nee=false"})), reference);
    const double nee = test::rmse(test::render(with({"render.spp=16", "render.nee=true", "render.mis=false"})), reference);
    const double mis = test::rmse(test::render(with({"render.spp=16", "render.nee=true", "render.mis=true"})), reference);
    std::printf("cornell_box 32x32, 16 spp, RMSE vs 1024 spp MIS: BSDF only %.4f, NEE only %.4f, MIS %.4f\n", bsdf, nee,
                mis);
    EXPECT_LT(mis, bsdf);
    EXPECT_LT(nee, bsdf);
}

TEST(TriangleLightVariant, ScenesWithoutEmissiveTrianglesCompileTheSameVariantAsBefore) {
    // Every scene in scenes/ with NEE on: the triangle-light define appears exactly when a mesh's
    // material emits, so other scenes' shaders are unchanged (absent features cost nothing).
    int withLights = 0, without = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(RAYLAB_SOURCE_DIR) + "/scenes")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().filename().string());
        const Scene scene = loadScene(entry.path(), {"render.nee=true"});
        bool emissiveMesh = false;
        for (const Mesh& m : scene.meshes) {
            for (std::size_t t = 0; t < m.triangles.size(); ++t) {   // glTF: per-triangle materials
                const Material& material = scene.materials[size_t(triangleMaterial(m, t))];
                const glm::vec3 L = material.radiance();
                // An emission texture makes no light (one radiance per light).
                emissiveMesh |= material.emissionTextureIndex < 0 && std::max({L.r, L.g, L.b}) > 0.0f;
            }
        }
        const ShaderDefines d = featureDefines(sceneFeatures(scene));
        const bool defined = std::any_of(d.begin(), d.end(), [](const auto& kv) { return kv.first == "RAYLAB_EMISSIVE_TRIANGLES" && kv.second == "1"; });
        EXPECT_EQ(defined, emissiveMesh);
        (emissiveMesh ? withLights : without) += 1;
        // Without NEE the feature is never on: BSDF rays score emission without it.
        const ShaderDefines off = featureDefines(sceneFeatures(loadScene(entry.path(), {"render.nee=false"})));
        EXPECT_TRUE(std::none_of(off.begin(), off.end(), [](const auto& kv) { return kv.first == "RAYLAB_EMISSIVE_TRIANGLES" && kv.second == "1"; }));
    }
    EXPECT_GE(withLights, 1) << "the Cornell box";
    EXPECT_GE(without, 3);
    SceneFeatures f = sceneFeatures(loadScene(test::scenePath("veach_mis.json")));
    EXPECT_EQ(featureName(f).find("triangle-lights"), std::string::npos);
}
