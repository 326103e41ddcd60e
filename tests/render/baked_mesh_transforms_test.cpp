// Small meshes' transforms baked into their vertices (render/baked_mesh_transforms.h): where the GPU
// scene does it, and that the vertices, normals and their precision far from the origin are right.
#include "render/baked_mesh_transforms.h"
#include "scene/scene_loader.h"
#include "scene/transform.h"
#include "render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab;

namespace {

Scene oneTriangle(const Transform& t) {
    Scene s;
    Mesh m;
    m.positions = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 1));
    m.normals = {n, n, n};
    m.triangles = {{0, 1, 2}};
    m.transform = t;
    s.meshes.push_back(m);
    s.textures.push_back(Texture{});
    return s;
}

} // namespace

TEST(BakedMeshTransforms, OnlyFewObjectsOfSmallMeshes) {
    EXPECT_TRUE(bakesMeshTransforms(loadScene(test::scenePath("cornell_box.json"))));
    EXPECT_TRUE(bakesMeshTransforms(loadScene(test::scenePath("textured_bricks.json"))));
    EXPECT_FALSE(bakesMeshTransforms(loadScene(test::scenePath("displaced_terrain.json")))) << "a large mesh";
    EXPECT_FALSE(bakesMeshTransforms(loadScene(test::scenePath("default.json")))) << "no mesh";
    Scene many = oneTriangle(Transform{});
    many.spheres.resize(16);
    EXPECT_FALSE(bakesMeshTransforms(many)) << "17 objects: a top-level BVH";
}

TEST(BakedMeshTransforms, VerticesGoWhereTheTransformPutsThemAndNormalsStayPerpendicular) {
    const Transform t{glm::vec3(1, 2, 3), glm::vec3(10, 20, 30), glm::vec3(2.0f, 0.5f, 1.5f)};
    const Scene s = oneTriangle(t);
    const Scene b = withMeshTransformsBaked(s);
    ASSERT_EQ(b.meshes.size(), 1u);
    EXPECT_EQ(b.meshes[0].transform, Transform{});
    EXPECT_TRUE(b.textures.empty()) << "the copy is for the geometry";
    const glm::mat4 toWorld = transformMatrix(t);
    for (int v = 0; v < 3; ++v) {
        const glm::vec3 want = glm::vec3(toWorld * glm::vec4(s.meshes[0].positions[v], 1.0f));
        EXPECT_LT(glm::length(b.meshes[0].positions[v] - want), 1e-5f) << v;
    }
    // A non-uniform scale: the normal follows the inverse transpose, so it stays perpendicular to
    // the baked triangle and on the same side.
    const auto& p = b.meshes[0].positions;
    const glm::vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    for (const glm::vec3& n : b.meshes[0].normals) {
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(n, glm::normalize(e1)), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(n, glm::normalize(e2)), 0.0f, 1e-5f);
        EXPECT_GT(glm::dot(n, glm::cross(e1, e2)), 0.0f);
    }
}

// Far from the world origin a float's step is 1/128 at 10^5: baked relative to the GPU's origin in
// double, the vertices keep the precision the camera-relative upload gives them.
TEST(BakedMeshTransforms, RelativeToAnOriginTheVerticesKeepTheirPrecision) {
    const glm::dvec3 origin(1e5, 0.0, -1e5);
    const Transform t{glm::vec3(float(1e5 + 0.3), 0.1f, float(-1e5 + 0.7)), glm::vec3(0, 30, 0), glm::vec3(1.0f)};
    const Scene b = withMeshTransformsBaked(oneTriangle(t), origin);
    const double c = std::cos(M_PI / 6.0), s = std::sin(M_PI / 6.0);
    const glm::dvec3 translation(t.translation);
    for (int v = 0; v < 3; ++v) {
        const glm::dvec3 p(oneTriangle(t).meshes[0].positions[v]);
        const glm::dvec3 world = translation + glm::dvec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
        const glm::dvec3 want = world - origin;
        EXPECT_LT(glm::length(glm::dvec3(b.meshes[0].positions[v]) - want), 1e-6) << v;
    }
}
