// The few-objects uniform block (render/few_objects.h): each instance's world box in the top
// level's order with a mesh flag and a mesh's triangle range, the spheres as the sphere buffer
// holds them, zeros after.
#include "render/few_objects.h"
#include "render_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace raylab;

namespace {

void expectBlockOf(const SceneGeometry& g) {
    const glsl::FewObjectsBlock block = fewObjectsBlock(g);
    ASSERT_LE(g.instances.size(), std::size_t(glsl::FEW_OBJECTS_MAX));
    for (std::size_t i = 0; i < std::size_t(glsl::FEW_OBJECTS_MAX); ++i) {
        if (i < g.instances.size()) {
            const glsl::GpuInstance& inst = g.instances[i];
            EXPECT_EQ(glm::vec3(block.boxMin[i]), glm::vec3(inst.worldMin)) << i;
            EXPECT_EQ(glm::vec3(block.boxMax[i]), glm::vec3(inst.worldMax)) << i;
            EXPECT_EQ(block.boxMin[i].w, inst.info.x == glsl::INSTANCE_MESH ? 1.0f : 0.0f) << i;
            // The range the pending-triangle loop takes up (bvh_traversal.glsl); none for a sphere.
            const glm::uvec4 range =
                inst.info.x == glsl::INSTANCE_MESH
                    ? glm::uvec4(glsl::instanceFirstTriangle(inst), glsl::instanceTriangleCount(inst), 0u, 0u)
                    : glm::uvec4(0u);
            EXPECT_EQ(block.triangles[i], range) << i;
        } else {
            EXPECT_EQ(block.boxMin[i], glm::vec4(0.0f)) << i;
            EXPECT_EQ(block.boxMax[i], glm::vec4(0.0f)) << i;
            EXPECT_EQ(block.triangles[i], glm::uvec4(0u)) << i;
        }
        if (i < g.spheres.size()) {
            EXPECT_EQ(block.spheres[i].centerRadius, g.spheres[i].centerRadius) << i;
            EXPECT_EQ(block.spheres[i].info, g.spheres[i].info) << i;
        } else {
            EXPECT_EQ(block.spheres[i].centerRadius, glm::vec4(0.0f)) << i;
        }
    }
}

} // namespace

TEST(FewObjects, TheBlockHoldsEachObjectsBoxTrianglesAndEachSphereInTopLevelOrder) {
    const SceneGeometry box = buildSceneGeometry(loadScene(test::scenePath("cornell_box.json")));
    ASSERT_EQ(box.instances.size(), 8u);
    expectBlockOf(box);
    // The ranges tile the box's 32 triangles: every triangle in exactly one object's range.
    const glsl::FewObjectsBlock ranges = fewObjectsBlock(box);
    std::vector<int> owners(box.triangles.size(), 0);
    for (std::size_t i = 0; i < box.instances.size(); ++i)
        for (unsigned t = ranges.triangles[i].x; t < ranges.triangles[i].x + ranges.triangles[i].y; ++t)
            ++owners.at(t);
    EXPECT_EQ(std::count(owners.begin(), owners.end(), 1), std::ptrdiff_t(box.triangles.size()));
    // Spheres and meshes mixed: the top level's order interleaves them, and each sphere's back-link
    // names its instance, whose box is flagged as no mesh.
    const SceneGeometry bricks = buildSceneGeometry(loadScene(test::scenePath("textured_bricks.json")));
    ASSERT_GT(bricks.spheres.size(), 0u);
    ASSERT_GT(bricks.instances.size(), bricks.spheres.size());
    expectBlockOf(bricks);
    const glsl::FewObjectsBlock block = fewObjectsBlock(bricks);
    for (std::size_t k = 0; k < bricks.spheres.size(); ++k) EXPECT_EQ(block.boxMin[block.spheres[k].info.y].w, 0.0f) << k;
}

TEST(FewObjects, AScenePastTheBlockKeepsItsFirstObjects) {
    Scene many = loadScene(test::scenePath("default.json"));
    while (many.spheres.size() <= std::size_t(glsl::FEW_OBJECTS_MAX)) many.spheres.push_back(many.spheres.back());
    const SceneGeometry g = buildSceneGeometry(many);
    const glsl::FewObjectsBlock block = fewObjectsBlock(g);
    const std::size_t last = std::size_t(glsl::FEW_OBJECTS_MAX) - 1;
    EXPECT_EQ(glm::vec3(block.boxMax[last]), glm::vec3(g.instances[last].worldMax));
    EXPECT_EQ(block.spheres[last].centerRadius, g.spheres[last].centerRadius);
}
