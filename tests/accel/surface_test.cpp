// The surface record at a hit (shaders/include/bvh_traversal.glsl surfaceAt, run on the CPU):
// positions, normals through non-uniform scales, smooth normals and uvs carried through.
#include "accel/cpu_traversal.h"
#include "scene/scene_loader.h"
#include "scene/transform.h"

#include <gtest/gtest.h>

using namespace raylab;

TEST(SurfaceAt, TransformedQuadGivesWorldNormalsSmoothNormalsAndUvs) {
    const Scene scene = parseScene(R"({ "objects": [ { "type": "mesh",
        "positions": [0, 0, 0,  1, 0, 0,  1, 1, 0,  0, 1, 0],
        "indices": [0, 1, 2,  0, 2, 3],
        "normals": [0, 0, 1,  0, 0, 1,  1, 0, 1,  0, 0, 1],
        "uvs": [0, 0,  1, 0,  1, 1,  0, 1],
        "transform": { "translation": [1, 2, 3], "rotation": [30, 40, 50], "scale": [2, 0.5, 3] } } ] })",
                                   "quad.json");
    const SceneGeometry g = buildSceneGeometry(scene);
    glsl::cpuTraversal.geometry = &g;
    const glm::mat4 m = transformMatrix(scene.meshes[0].transform);
    auto world = [&](glm::vec3 p) { return glm::vec3(m * glm::vec4(p, 1.0f)); };
    const glm::vec3 target = world(glm::vec3(0.75f, 0.25f, 0.0f));   // in the first triangle
    const glm::vec3 e1 = world(glm::vec3(1, 0, 0)) - world(glm::vec3(0)), e2 = world(glm::vec3(0, 1, 0)) - world(glm::vec3(0));
    const glm::vec3 exactNormal = glm::normalize(glm::cross(e1, e2));
    const glsl::Ray ray(target + 5.0f * exactNormal + 0.3f * e1, -5.0f * exactNormal - 0.3f * e1);
    glsl::TraceRecord rec{};
    ASSERT_TRUE(glsl::traceScene(ray, glsl::FLOAT_MAX, false, rec));
    const glsl::SurfaceHit s = glsl::surfaceAt(ray, rec);
    EXPECT_NEAR(glm::length(s.position - target), 0.0f, 1e-5f);
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(s.position[k] - target[k]), s.error[k] + 1e-6f);
    // The geometric normal is perpendicular to the world-space edges despite the uneven scale.
    EXPECT_NEAR(std::abs(glm::dot(s.normal, exactNormal)), 1.0f, 1e-5f);
    // Smooth normal: interpolated (vertex 2 leans towards +x), transformed by the inverse
    // transpose, normalised; it differs from the geometric one.
    // Barycentrics of (0.75, 0.25) in the triangle (0,0) (1,0) (1,1): 0.25, 0.5, 0.25.
    const glm::vec3 nObj = glm::normalize(0.25f * glm::vec3(0, 0, 1) + 0.5f * glm::vec3(0, 0, 1) +
                                          0.25f * glm::normalize(glm::vec3(1, 0, 1)));
    const glm::vec3 nWorld = glm::normalize(glm::transpose(glm::inverse(glm::mat3(m))) * nObj);
    EXPECT_NEAR(glm::length(s.shadingNormal - nWorld), 0.0f, 1e-4f);
    EXPECT_LT(glm::dot(s.shadingNormal, s.normal), 0.99f);
    EXPECT_NEAR(s.uv.x, 0.75f, 1e-5f);
    EXPECT_NEAR(s.uv.y, 0.25f, 1e-5f);
    glsl::cpuTraversal.geometry = nullptr;
}

TEST(SurfaceAt, SphereUvIsLongitudeAndLatitude) {
    const Scene scene = parseScene(R"({ "objects": [ { "type": "sphere", "center": [1, 2, 3], "radius": 2 } ] })", "s.json");
    const SceneGeometry g = buildSceneGeometry(scene);
    glsl::cpuTraversal.geometry = &g;
    const glm::vec3 c(1, 2, 3);
    const struct { glm::vec3 side; glm::vec2 uv; } cases[] = {
        {{1, 0, 0}, {0.5f, 0.5f}}, {{0, 0, 1}, {0.75f, 0.5f}}, {{0, 0, -1}, {0.25f, 0.5f}},
        {{0, 1, 0}, {0.5f, 1.0f}}, {{0, -1, 0}, {0.5f, 0.0f}}};
    for (const auto& k : cases) {
        const glsl::Ray ray(c + 10.0f * k.side + glm::vec3(1e-4f, 0, 0) * std::abs(k.side.y), -k.side);
        glsl::TraceRecord rec{};
        ASSERT_TRUE(glsl::traceScene(ray, glsl::FLOAT_MAX, false, rec));
        const glsl::SurfaceHit s = glsl::surfaceAt(ray, rec);
        if (std::abs(k.side.y) < 0.5f) {   // at the poles u is arbitrary
            EXPECT_NEAR(s.uv.x, k.uv.x, 1e-4f) << k.side.x << k.side.y << k.side.z;
        }
        EXPECT_NEAR(s.uv.y, k.uv.y, 1e-3f) << k.side.x << k.side.y << k.side.z;
    }
    glsl::cpuTraversal.geometry = nullptr;
}
