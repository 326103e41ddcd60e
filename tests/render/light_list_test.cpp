// The light list (render/light_list.h): the alias table picks each light with probability
// proportional to its weight exactly; emissive triangles are collected in world space with their
// areas and powers, and each triangle knows its light index.
#include "render/light_list.h"
#include "render/shader_variant.h"
#include "render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace raylab;

namespace {

// Probability of each index implied by an alias table: column i kept with q_i, else alias_i.
std::vector<double> impliedProbabilities(const std::vector<glm::vec4>& table) {
    std::vector<double> p(table.size(), 0.0);
    const double n = double(table.size());
    for (const glm::vec4& e : table) {
        p[size_t(e.y)] += (1.0 - double(e.x)) / n;
        p[size_t(&e - table.data())] += double(e.x) / n;
    }
    return p;
}

// Each material's radiance, as the GPU scene hands it to buildLightList.
std::vector<glm::vec3> materialRadiance(const Scene& scene) {
    std::vector<glm::vec3> radiance;
    for (const Material& m : scene.materials) radiance.push_back(m.radiance());
    return radiance;
}

} // namespace

TEST(LightList, AliasTableReproducesTheWeights) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (size_t n : {1u, 2u, 3u, 17u, 1000u}) {
        SCOPED_TRACE(n);
        std::vector<double> w(n);
        double total = 0.0;
        for (size_t i = 0; i < n; ++i) total += w[i] = (i % 5 == 3) ? 0.0 : std::pow(uniform(rng), 4.0) + 1e-3;
        const auto table = buildAliasTable(w);
        ASSERT_EQ(table.size(), n);
        const auto p = impliedProbabilities(table);
        for (size_t i = 0; i < n; ++i) {
            EXPECT_NEAR(p[i], w[i] / total, 1e-6) << i;
            EXPECT_NEAR(table[i].z, w[i] / total, 1e-7) << "pmf " << i;
            EXPECT_EQ(table[i].w, table[size_t(table[i].y)].z) << "pmf of the alias " << i;
            EXPECT_GE(table[i].x, 0.0f);
            EXPECT_LE(table[i].x, 1.0f);
            if (w[i] == 0.0) {
                EXPECT_EQ(p[i], 0.0) << "a zero weight is never picked";
            }
        }
    }
    EXPECT_THROW(buildAliasTable({0.0, 0.0}), std::invalid_argument);
    EXPECT_TRUE(buildAliasTable({}).empty());
}

TEST(LightList, CornellBoxLightIsTwoTrianglesWithTheirAreaAndPower) {
    const Scene scene = loadScene(test::scenePath("cornell_box.json"));
    const SceneGeometry g = buildSceneGeometry(scene);
    const std::vector<glm::vec3> radiance = materialRadiance(scene);
    const LightList lights = buildLightList(scene, g, radiance);
    EXPECT_TRUE(lights.spheres.empty());
    ASSERT_EQ(lights.triangles.size(), 2u);
    double area = 0.0;
    for (const auto& t : lights.triangles) {
        area += t.p0Area.w;
        EXPECT_EQ(glm::vec3(t.radiance), glm::vec3(17, 12, 4));
        EXPECT_FLOAT_EQ(t.p0Area.y, 548.7f);
    }
    EXPECT_NEAR(area, 130.0 * 105.0, 1e-3);   // 343..213 × 227..332
    ASSERT_EQ(lights.power.size(), 2u);
    // One-sided (emission_sides front): power = luminance × π·A over the front hemisphere alone,
    // the factor π common to every light and left out.
    EXPECT_NEAR(lights.power[0] + lights.power[1], (0.2126 * 17 + 0.7152 * 12 + 0.0722 * 4) * 1.0 * 130.0 * 105.0, 1e-2);
    int marked = 0;
    for (std::uint32_t i : lights.triangleLightIndex) marked += i > 0 ? 1 : 0;
    EXPECT_EQ(marked, 2);
}

TEST(LightList, TrianglesArePlacedByTheirTransformAndSpheresComeFirst) {
    Scene scene = parseScene(R"({
      "materials": { "lamp": { "emission": 1, "strength": 2 }, "matte": { "albedo": 0.5 } },
      "objects": [
        { "type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "lamp" },
        { "type": "sphere", "center": [3, 0, 0], "radius": 0.5, "material": "matte" },
        { "type": "mesh", "material": "matte", "positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0, 1, 2] },
        { "type": "mesh", "material": "lamp", "positions": [0,0,0, 1,0,0, 0,1,0, 5,5,5], "indices": [0, 1, 2, 0, 0, 3],
          "transform": { "translation": [0, 0, 4], "scale": [2, 2, 2] } }
      ] })", "lights.json");
    const SceneGeometry g = buildSceneGeometry(scene);
    const std::vector<glm::vec3> radiance = materialRadiance(scene);
    const LightList lights = buildLightList(scene, g, radiance);
    ASSERT_EQ(lights.spheres.size(), 1u);
    ASSERT_EQ(lights.triangles.size(), 1u) << "the degenerate triangle is no light";
    EXPECT_FLOAT_EQ(lights.triangles[0].p0Area.w, 2.0f);   // ½ · 2 · 2
    EXPECT_FLOAT_EQ(lights.triangles[0].p0Area.z, 4.0f);
    ASSERT_EQ(lights.power.size(), 2u);
    EXPECT_NEAR(lights.power[0], 2.0 * 4.0 * M_PI * 0.25, 1e-5);   // sphere: luminance × 4πr²
    EXPECT_NEAR(lights.power[1], 2.0 * 2.0 * 2.0, 1e-5);           // triangle: luminance × 2 · area
    // Triangle 1 (the first mesh's) is no light; the lamp mesh's non-degenerate one is light 1.
    ASSERT_EQ(lights.triangleLightIndex.size(), 3u);
    EXPECT_EQ(lights.triangleLightIndex[0], 0u);
    int lit = 0;
    for (size_t i = 1; i < 3; ++i) lit += lights.triangleLightIndex[i] == 1u ? 1 : 0;
    EXPECT_EQ(lit, 1);
    // Each sphere knows its light (1 + index; 0: none), which an emitter hit's MIS weight reads.
    ASSERT_EQ(lights.sphereLightIndex.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        const bool lamp = g.spheres[k].centerRadius.x == 0.0f;
        EXPECT_EQ(lights.sphereLightIndex[k], lamp ? 1u : 0u) << k;
    }
}

// Spheres in the top level's order, lights among them in that order: each knows its own, which
// the GPU scene writes into its record (GpuSphere info.z) for an emitter hit's MIS weight.
TEST(LightList, EachSphereKnowsItsLight) {
    Scene scene = parseScene(R"({
      "materials": { "lamp": { "emission": 1, "strength": 1 }, "matte": { "albedo": 0.5 } },
      "objects": [
        { "type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "matte" },
        { "type": "sphere", "center": [3, 0, 0], "radius": 0.5, "material": "lamp" },
        { "type": "sphere", "center": [6, 0, 0], "radius": 0.5, "material": "lamp" },
        { "type": "sphere", "center": [9, 0, 0], "radius": 0.5, "material": "matte" }
      ] })", "spheres.json");
    const SceneGeometry g = buildSceneGeometry(scene);
    const std::vector<glm::vec3> radiance = materialRadiance(scene);
    const LightList lights = buildLightList(scene, g, radiance);
    ASSERT_EQ(lights.spheres.size(), 2u);
    ASSERT_EQ(lights.sphereLightIndex.size(), 4u);
    for (std::size_t k = 0; k < g.spheres.size(); ++k) {
        const std::uint32_t light = lights.sphereLightIndex[k];
        if (radiance.at(g.spheres[k].info.x) == glm::vec3(0.0f)) {
            EXPECT_EQ(light, 0u) << k;
        } else {
            ASSERT_GE(light, 1u) << k;
            EXPECT_EQ(lights.spheres.at(light - 1).centerRadius, g.spheres[k].centerRadius) << k;
        }
    }
}

TEST(LightList, PowerSelectionOnlyWhenLightsDifferInPower) {
    // Equal-power lamps (the Veach scene: strength × r² within 0.3%) and the Cornell box's two
    // equal triangles are picked uniformly; a lamp twice as strong switches power selection on.
    EXPECT_FALSE(lightPowersDiffer(loadScene(test::scenePath("veach_mis.json"))));
    EXPECT_FALSE(lightPowersDiffer(loadScene(test::scenePath("cornell_box.json"))));
    EXPECT_TRUE(lightPowersDiffer(loadScene(test::scenePath("veach_mis.json"), {"materials.lamp_xs.strength=1600"})));
    Scene cornell = loadScene(test::scenePath("cornell_box.json"));
    int light = -1;
    for (size_t i = 0; i < cornell.materials.size(); ++i)
        if (cornell.materials[i].name == "light") light = int(i);
    ASSERT_GE(light, 0);
    cornell.spheres.push_back(Sphere{glm::vec3(278, 100, 200), 20.0f, light, {}});
    EXPECT_TRUE(lightPowersDiffer(cornell));
    EXPECT_EQ(featureName(sceneFeatures(cornell)).find("light-power") != std::string::npos, true);
}

TEST(LightList, MeshHasEmissiveTriangleLooksAtTheMaterialsItsTrianglesUse) {
    Scene scene;
    Material dark, lamp, textured;
    lamp.emission = glm::vec3(1.0f);
    lamp.emissionStrength = 2.0f;
    textured = lamp;
    textured.emissionTextureIndex = 0;   // varies its emission: no light (lightRadiance 0)
    scene.materials = {dark, lamp, textured};
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    mesh.material = 1;
    EXPECT_TRUE(meshHasEmissiveTriangle(scene, mesh)) << "one material for all: the mesh's";
    mesh.material = 2;
    EXPECT_FALSE(meshHasEmissiveTriangle(scene, mesh)) << "a textured emitter is no light";
    mesh.material = 0;
    mesh.triangleMaterials = {-1, 1};   // glTF: the second triangle's own material emits
    EXPECT_TRUE(meshHasEmissiveTriangle(scene, mesh));
    mesh.triangleMaterials = {-1, 0};
    EXPECT_FALSE(meshHasEmissiveTriangle(scene, mesh));
    mesh.material = 1;
    mesh.triangleMaterials = {-1, 0};   // -1: the mesh's own, which emits
    EXPECT_TRUE(meshHasEmissiveTriangle(scene, mesh));
    mesh.triangles.clear();
    mesh.triangleMaterials.clear();
    EXPECT_FALSE(meshHasEmissiveTriangle(scene, mesh)) << "no triangles, no light";
}
