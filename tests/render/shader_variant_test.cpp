// Per-scene specialisation: the feature set, the variant cache, and that the all-features shader
// computes the same thing.
#include "render/shader_variant.h"
#include "render_helpers.h"
#include "support/gl_test.h"
#include "support/statistics.h"

#include <algorithm>
#include <cmath>

using namespace raylab;

namespace {

// The defines of the features that are on (featureDefines emits the others as 0); the stage and
// the sampler are choices, the object counts numbers, not features.
ShaderDefines on(const ShaderDefines& defines) {
    ShaderDefines d;
    for (const auto& define : defines)
        if (define.second != "0" && define.first != "RAYLAB_STAGE" && define.first != "RAYLAB_SAMPLER" &&
            define.first != "RAYLAB_OBJECT_COUNT" && define.first != "RAYLAB_SPHERE_COUNT")
            d.push_back(define);
    return d;
}

std::string defineValue(const ShaderDefines& defines, const std::string& name) {
    for (const auto& [n, value] : defines)
        if (n == name) return value;
    return "absent";
}

} // namespace

TEST(ShaderVariant, FeaturesComeFromTheScene) {
    // The estimator of the old defaults, whose variant has no NEE, no adaptive sampling and no
    // sampler in its name.
    const Scene spheres = loadScene(test::scenePath("default.json"),
                                    {"render.nee=false", "render.sampler=independent", "render.adaptive=false"});
    EXPECT_EQ(featureName(sceneFeatures(spheres)), "spheres+few-objects");
    Scene s = spheres;
    s.meshes.push_back(Mesh{});
    s.meshes[0].normals.push_back(glm::vec3(0, 0, 1));
    s.camera.aperture = 0.1f;
    EXPECT_EQ(featureName(sceneFeatures(s)), "spheres+meshes+smooth+dof+few-objects+small-meshes+meshes-in-world");
    s.meshes.push_back(s.meshes[0]);
    s.meshes[1].transform.translation.x = 1.0f;
    EXPECT_EQ(featureName(sceneFeatures(s)), "spheres+meshes+smooth+dof+few-objects+small-meshes+meshes-in-world")
        << "meshes placed by different transforms: baked into their vertices, all placed by the identity";
    for (int i = 0; i < 20; ++i) s.spheres.push_back(Sphere{});
    EXPECT_EQ(featureName(sceneFeatures(s)), "spheres+meshes+smooth+dof") << "many objects: top-level BVH";
    const ShaderDefines d = on(featureDefines(sceneFeatures(spheres)));
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d[0].first, "RAYLAB_FEATURES_SPECIALISED");
    EXPECT_EQ(d[1].first, "RAYLAB_FEATURE_SPHERES");
    EXPECT_EQ(d[2].first, "RAYLAB_TOP_LEVEL_LINEAR");
    // 5 geometry features + NEE, BSDF, sky map + roughness, metallic, emission, specular textures,
    // wrap modes + triangle lights, sphere lights, the sky as a light, light power selection +
    // point/spot/distant lights, one-sided emitters
    EXPECT_EQ(on(featureDefines(allFeatures())).size(), 20u);
}

// Next-event estimation's sphere lights and the sky as a light are compiled in only where the
// scene has them: the Cornell box (a triangle lamp, a black sky) has neither.
TEST(ShaderVariant, SphereLightsAndTheSkyLightOnlyWhereTheSceneHasThem) {
    const auto kinds = [](const Scene& s) {
        const SceneFeatures f = sceneFeatures(s);
        return std::string(f.sphereLights ? "spheres" : "-") + "/" + (f.skyLight ? "sky" : "-");
    };
    Scene box = loadScene(test::scenePath("cornell_box.json"));
    EXPECT_EQ(kinds(box), "-/-");
    box.sky.color = glm::vec3(0.0f, 0.0f, 0.1f);
    EXPECT_EQ(kinds(box), "-/sky") << "a sky above 0 gives light";
    box.sky.strength = 0.0f;
    EXPECT_EQ(kinds(box), "-/-") << "strength 0: no light";
    box.sky.type = Sky::Type::Gradient;
    box.sky.strength = 1.0f;
    box.sky.top = glm::vec3(0.0f);
    box.sky.bottom = glm::vec3(0.2f);
    EXPECT_EQ(kinds(box), "-/sky") << "a gradient bright below";
    box.sky.type = Sky::Type::Map;
    EXPECT_EQ(kinds(box), "-/sky") << "a map: its texels decide at run time";
    Sphere grey;
    grey.material = 0;   // no emission
    ASSERT_FALSE(box.materials[0].name == "light");
    box.spheres.push_back(grey);
    EXPECT_EQ(kinds(box), "-/sky") << "a sphere that does not emit is no light";
    Sphere lamp = grey;
    lamp.material = int(std::find_if(box.materials.begin(), box.materials.end(),
                                     [](const Material& m) { return m.name == "light"; }) - box.materials.begin());
    ASSERT_LT(std::size_t(lamp.material), box.materials.size());
    box.spheres.push_back(lamp);
    EXPECT_EQ(kinds(box), "spheres/sky");
    box.render.nee = false;
    EXPECT_EQ(kinds(box), "-/-") << "without next-event estimation no light is sampled";
    EXPECT_EQ(kinds(loadScene(test::scenePath("default.json"))), "spheres/sky");
}

// With few objects the variant fixes their number and the spheres' (the loops' trip counts); with
// the top-level BVH both are 0, the loops reading the buffers' lengths.
TEST(ShaderVariant, FewObjectsFixTheirCounts) {
    const auto counts = [](const Scene& s) {
        const ShaderDefines d = featureDefines(sceneFeatures(s));
        return defineValue(d, "RAYLAB_OBJECT_COUNT") + "/" + defineValue(d, "RAYLAB_SPHERE_COUNT");
    };
    Scene box = loadScene(test::scenePath("cornell_box.json"));
    EXPECT_EQ(counts(box), "8/0") << "eight meshes";
    box.spheres.push_back(Sphere{});
    EXPECT_EQ(counts(box), "9/1");
    EXPECT_EQ(counts(loadScene(test::scenePath("default.json"))), "8/8");
    for (int i = 0; i < 20; ++i) box.spheres.push_back(Sphere{});
    EXPECT_EQ(counts(box), "0/0") << "many objects: the top-level BVH";
    EXPECT_EQ(defineValue(featureDefines(allFeatures()), "RAYLAB_OBJECT_COUNT"), "0");
}

// A scene of few objects whose meshes all have at most kSmallMeshMax triangles searches them
// without their BVHs; one larger mesh, or a top-level BVH, and every mesh is walked.
TEST(ShaderVariant, SmallMeshesAreThoseOfAtMostSixteenTriangles) {
    const auto small = [](const Scene& s) {
        for (const auto& [name, value] : featureDefines(sceneFeatures(s)))
            if (name == "RAYLAB_SMALL_MESHES") return value == "1";
        ADD_FAILURE() << "no RAYLAB_SMALL_MESHES define";
        return false;
    };
    Scene box = loadScene(test::scenePath("cornell_box.json"));
    EXPECT_TRUE(small(box)) << "walls of 2 triangles, blocks of 10";
    const Scene terrain = loadScene(test::scenePath("displaced_terrain.json"));
    EXPECT_FALSE(small(terrain));
    EXPECT_FALSE(small(loadScene(test::scenePath("default.json")))) << "no meshes";
    box.meshes[0].triangles.resize(kSmallMeshMax, box.meshes[0].triangles[0]);
    EXPECT_TRUE(small(box));
    box.meshes[0].triangles.push_back(box.meshes[0].triangles[0]);
    EXPECT_FALSE(small(box)) << kSmallMeshMax + 1 << " triangles";
    box.meshes[0].triangles.resize(2);
    for (int i = 0; i < 20; ++i) box.spheres.push_back(Sphere{});
    EXPECT_FALSE(small(box)) << "many objects: the top-level BVH";
}

TEST(ShaderVariant, ScenesWithoutTheNewTextureKindsCompileTheSameDefinesAsBefore) {
    // textured_bricks.json has albedo and normal textures only: exactly the defines it had before
    // roughness, metallic and emission textures existed.
    const Scene bricks = loadScene(test::scenePath("textured_bricks.json"));
    ShaderDefines expected = {{"RAYLAB_FEATURES_SPECIALISED", "1"}};
    const SceneFeatures f = sceneFeatures(bricks);
    if (f.spheres) expected.emplace_back("RAYLAB_FEATURE_SPHERES", "1");
    if (f.meshes) expected.emplace_back("RAYLAB_FEATURE_MESHES", "1");
    if (f.smoothNormals) expected.emplace_back("RAYLAB_FEATURE_SMOOTH_NORMALS", "1");
    expected.emplace_back("RAYLAB_FEATURE_TEXTURES", "1");
    if (f.linearTopLevel) expected.emplace_back("RAYLAB_TOP_LEVEL_LINEAR", "1");
    if (f.linearTopLevel && f.smallMeshes) expected.emplace_back("RAYLAB_SMALL_MESHES", "1");
    if (f.meshesInWorld) expected.emplace_back("RAYLAB_MESHES_IN_WORLD", "1");
    if (f.nee) expected.emplace_back("RAYLAB_NEE", "1");
    if (f.generalBsdf) expected.emplace_back("RAYLAB_GENERAL_BSDF", "1");
    if (f.sphereLights) expected.emplace_back("RAYLAB_SPHERE_LIGHTS", "1");
    if (f.skyLight) expected.emplace_back("RAYLAB_SKY_LIGHT", "1");
    if (f.adaptive) expected.emplace_back("RAYLAB_ADAPTIVE", "1");
    EXPECT_EQ(on(featureDefines(f)), expected);
    // Each new kind adds its own define and nothing else.
    // The defines the edits add come before the light kinds and RAYLAB_ADAPTIVE (features.glsl).
    const auto withOne = [&](auto edit, const char* define) {
        Scene s = bricks;
        edit(s);
        ShaderDefines d = on(featureDefines(sceneFeatures(s)));
        ShaderDefines more = expected;
        const auto adaptive = [&] {
            return std::find_if(more.begin(), more.end(), [](const auto& define) {
                return define.first == "RAYLAB_SPHERE_LIGHTS" || define.first == "RAYLAB_SKY_LIGHT" ||
                       define.first == "RAYLAB_ADAPTIVE";
            });
        };
        if (std::find(more.begin(), more.end(), std::pair<std::string, std::string>{"RAYLAB_GENERAL_BSDF", "1"}) ==
                more.end() && sceneFeatures(s).generalBsdf)
            more.emplace(adaptive(), "RAYLAB_GENERAL_BSDF", "1");
        more.emplace(adaptive(), define, "1");
        EXPECT_EQ(d, more) << define;
    };
    withOne([](Scene& s) { s.materials[0].roughnessTextureIndex = 0; }, "RAYLAB_TEXTURE_ROUGHNESS");
    withOne([](Scene& s) { s.materials[0].emissionTextureIndex = 0; }, "RAYLAB_TEXTURE_EMISSION");
    withOne([](Scene& s) { s.materials[0].metallicTextureIndex = 0; }, "RAYLAB_TEXTURE_METALLIC");
    withOne([](Scene& s) { s.materials[0].specularTextureIndex = 0; }, "RAYLAB_TEXTURE_SPECULAR");
    withOne([](Scene& s) { s.textures[0].wrapU = TextureWrap::ClampToEdge; }, "RAYLAB_TEXTURE_WRAP_MODES");
    // Metallic without any texture of its own on an untextured material is baked: no new define.
    Scene metal = loadScene(test::scenePath("default.json"));
    metal.materials[0].metallic = 0.5f;
    for (const auto& [name, value] : on(featureDefines(sceneFeatures(metal)))) EXPECT_EQ(name.find("RAYLAB_TEXTURE_"), std::string::npos);
    EXPECT_TRUE(sceneFeatures(metal).generalBsdf);
}

class ShaderVariantTest : public test::GlTest {};

TEST_F(ShaderVariantTest, VariantsAreNamedCompiledOnceAndReused) {
    const Scene spheres = loadScene(test::scenePath("furnace.json"), {"render.sampler=independent"});
    Scene lens = spheres;
    lens.camera.aperture = 0.01f;
    PathTracer tracer;
    EXPECT_EQ(tracer.compileSeconds(), 0.0);
    tracer.setScene(spheres);
    EXPECT_EQ(tracer.variantName(), "fragment [spheres+few-objects+adaptive]");
    const double first = tracer.compileSeconds();
    EXPECT_GT(first, 0.0);
    tracer.setScene(lens);
    EXPECT_EQ(tracer.variantName(), "fragment [spheres+dof+few-objects+adaptive]");
    tracer.setScene(spheres);
    EXPECT_EQ(tracer.compileSeconds(), first) << "the cached program, not a new compile";
    TracerOptions all;
    all.specialise = false;
    PathTracer unspecialised(all);
    unspecialised.setScene(spheres);
    EXPECT_EQ(unspecialised.variantName(), "fragment [all features]");
}

TEST_F(ShaderVariantTest, AllFeaturesShaderPassesTheFurnaceExactly) {
    const Scene scene = loadScene(test::scenePath("furnace.json"));
    TracerOptions all;
    all.specialise = false;
    const Image image = test::render(scene, all);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) ASSERT_NEAR(image.rgb(x, y)[0], 0.5f, 1e-6f);
}

TEST_F(ShaderVariantTest, TraversalCountersCountBoxesAndTriangles) {
    TracerOptions counting;
    counting.extraDefines = {{"RAYLAB_COUNT_TRAVERSAL", "1"}};
    Scene scene = loadScene(test::scenePath("furnace.json"), {"render.spp=1"});
    PathTracer tracer(counting);
    tracer.setScene(scene);
    tracer.renderPass();
    EXPECT_GT(tracer.raysTraced(), 0u);
    EXPECT_EQ(tracer.boxTests(), 0u) << "one sphere: no top-level BVH, no boxes";
    EXPECT_EQ(tracer.triangleTests(), 0u) << "spheres only";
    scene.meshes.push_back(parseScene(R"({ "objects": [ { "type": "mesh", "positions": [-50,-50,3, 50,-50,3, 0,50,3],
        "indices": [0, 1, 2] } ] })", "tri.json").meshes[0]);
    tracer.setScene(scene);
    tracer.renderPass();
    EXPECT_GT(tracer.triangleTests(), 0u) << "bounce rays towards +z meet the triangle behind the camera";
    EXPECT_GE(tracer.boxTests(), tracer.triangleTests()) << "the mesh's root box before its triangle";
}

TEST_F(ShaderVariantTest, SpecialisedAndAllFeaturesAgreeOnTheCornellBox) {
    // Meshes, few objects, no textures: the specialised shader and the one with every feature
    // (top-level BVH, textures, DOF, smooth normals compiled in) estimate the same image. The
    // all-features shader draws a lens sample, so the two are independent renders: the per-pixel
    // difference must have mean 0 within 4 standard errors (fixed seeds).
    const Scene scene = loadScene(test::scenePath("cornell_box.json"),
                                  {"render.width=16", "render.height=16", "render.spp=64"});
    TracerOptions all;
    all.specialise = false;
    const Image a = test::render(scene);
    const Image b = test::render(scene, all);
    for (int c = 0; c < 3; ++c) {
        std::vector<double> d;
        for (size_t i = size_t(c); i < a.rgba.size(); i += 4) d.push_back(double(a.rgba[i]) - double(b.rgba[i]));
        const double m = test::mean(d), se = test::standardError(d);
        EXPECT_GT(se, 0.0);
        EXPECT_LT(std::abs(m), 4.0 * se) << "channel " << c << " mean difference " << m;
        EXPECT_GT(test::mean(test::channel(a, c)), 0.01) << "the box is lit";
    }
}
