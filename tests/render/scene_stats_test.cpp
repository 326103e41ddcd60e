// Scene statistics (render/scene_stats.h) against scenes whose contents are known by hand.
#include "render/scene_stats.h"

#include "render/render_helpers.h"

#include <gtest/gtest.h>

#include <functional>

namespace raylab {
namespace {

// Nodes reachable from `root` in a depth-first flattened BVH (interior: first child follows, the
// second is its link); counts leaves too.
std::size_t reachable(const std::vector<glsl::GpuBvhNode>& nodes, std::uint32_t root, std::size_t& leaves) {
    std::size_t n = 0;
    std::function<void(std::uint32_t)> walk = [&](std::uint32_t i) {
        ++n;
        if (glsl::bvhNodeIsLeaf(nodes.at(i))) {
            ++leaves;
            return;
        }
        walk(i + 1);
        walk(glsl::bvhNodeLink(nodes.at(i)));
    };
    walk(root);
    return n;
}

TEST(SceneStats, CornellBoxCountsWhatTheFileHolds) {
    const Scene scene = loadScene(test::scenePath("cornell_box.json"));
    const SceneGeometry g = buildSceneGeometry(scene);
    const SceneStats s = sceneStats(scene, g);
    EXPECT_EQ(s.objects, 8u);
    EXPECT_EQ(s.spheres, 0u);
    EXPECT_EQ(s.instances, 8u);
    EXPECT_EQ(s.triangles, 6u * 2u + 2u * 10u);   // six quads, two blocks of five quads
    EXPECT_EQ(s.vertices, 6u * 4u + 2u * 20u);
    EXPECT_EQ(s.materials, 4u);
    EXPECT_EQ(s.emissiveSpheres, 0u);
    EXPECT_EQ(s.emissiveTriangles, 2u);   // the light quad
    EXPECT_EQ(s.textures, 0u);
    EXPECT_EQ(s.textureBytes, 0u);
    // Every node is part of a tree: the top level's from node 0, each mesh's from its root; a
    // binary tree has one interior node fewer than leaves.
    std::size_t leaves = 0;
    EXPECT_EQ(reachable(g.topNodes, 0, leaves), s.topBvhNodes);
    EXPECT_EQ(s.topBvhNodes, 2 * leaves - 1);
    std::size_t meshNodes = 0;
    for (std::uint32_t root : g.meshRoot) {
        std::size_t l = 0;
        const std::size_t n = reachable(g.meshNodes, root, l);
        EXPECT_EQ(n, 2 * l - 1);
        meshNodes += n;
    }
    EXPECT_EQ(meshNodes, s.meshBvhNodes);
    EXPECT_GE(s.meshBvhNodes, 8u);   // at least a root per mesh
    EXPECT_GE(s.bvhDepth, 1);
}

TEST(SceneStats, TextureMemoryCountsEveryMipLevelAsFloatRgba) {
    const Scene scene = loadScene(test::scenePath("textured_bricks.json"));
    const SceneStats s = sceneStats(scene, buildSceneGeometry(scene));
    EXPECT_EQ(s.objects, 6u);
    EXPECT_EQ(s.spheres, 4u);
    EXPECT_EQ(s.instances, 2u);
    EXPECT_EQ(s.triangles, 12u + 2u);
    EXPECT_EQ(s.emissiveSpheres, 1u);   // the lamp
    EXPECT_EQ(s.emissiveTriangles, 0u);
    // bricks.ppm (sRGB albedo, shared by two materials) and bricks_normal.ppm (linear): two
    // 128 x 128 pyramids of 128² + 64² + ... + 1 = 21845 texels, 16 bytes each, and the table
    // (header, 6 materials, 2 textures) of 16-byte rows.
    EXPECT_EQ(s.textures, 2u);
    EXPECT_EQ(s.textureBytes, 2u * 21845u * 16u + (1u + 6u + 2u) * 16u);
    EXPECT_EQ(formatBytes(s.textureBytes), "682.8 KiB");
}

TEST(SceneStats, CountsTheLightListPerTriangleMaterialsAndAnalyticLights) {
    // A glTF that Blender exported, its checker plane made emissive: its triangles are lights by
    // their own glTF material (the mesh's is the default); a black point light is no light.
    Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/tests/data/blender_suzanne/suzanne.json");
    int checker = -1;
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name.find("checker") != std::string::npos) checker = int(i);
    ASSERT_GE(checker, 0);
    scene.materials[size_t(checker)].emission = glm::vec3(1.0f);
    scene.materials[size_t(checker)].emissionStrength = 2.0f;
    const Mesh& mesh = scene.meshes.at(0);
    std::size_t expected = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) expected += mesh.triangleMaterials.at(t) == checker ? 1 : 0;
    ASSERT_GT(expected, 0u);
    ASSERT_LT(expected, mesh.triangles.size());
    Light point, sun, black;
    sun.type = Light::Type::Distant;
    black.intensity = glm::vec3(0.0f);
    scene.lights = {point, sun, black};
    const SceneStats s = sceneStats(scene, buildSceneGeometry(scene));
    EXPECT_EQ(s.emissiveTriangles, expected);
    EXPECT_EQ(s.emissiveSpheres, 1u);   // the lamp
    EXPECT_EQ(s.analyticLights, 2u);
    EXPECT_NE(describeSceneStats(s).find("2 point/spot/distant"), std::string::npos);
}

TEST(SceneStats, DescriptionNamesEveryFigure) {
    const Scene scene = loadScene(test::scenePath("cornell_box.json"));
    const std::string d = describeSceneStats(sceneStats(scene, buildSceneGeometry(scene)));
    for (const char* part : {"8 objects", "32 triangles", "mesh nodes", "0 textures", "2 emissive triangles"})
        EXPECT_NE(d.find(part), std::string::npos) << part << " in:\n" << d;
}

} // namespace
} // namespace raylab
