// The few-objects uniform block (render/few_objects.h): each instance's world box in the top
// level's order with a mesh flag, the spheres as the sphere buffer holds them, zeros after.
#include "render/few_objects.h"
#include "render_helpers.h"

#include <gtest/gtest.h>

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
        } else {
            EXPECT_EQ(block.boxMin[i], glm::vec4(0.0f)) << i;
            EXPECT_EQ(block.boxMax[i], glm::vec4(0.0f)) << i;
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

TEST(FewObjects, TheBlockHoldsEachObjectsBoxAndEachSphereInTopLevelOrder) {
    const SceneGeometry box = buildSceneGeometry(loadScene(test::scenePath("cornell_box.json")));
    ASSERT_EQ(box.instances.size(), 8u);
    expectBlockOf(box);
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
