// Click-to-focus without a window: the focus distance is the hit's depth along the view axis (the
// plane the thin lens of camera.glsl focuses on), for spheres and transformed meshes.
#include "app/focus_pick.h"

#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab::ui {
namespace {

Scene lookingDownMinusZ() {
    Scene s;
    s.camera.position = glm::vec3(0.0f, 0.0f, 0.0f);
    s.camera.lookAt = glm::vec3(0.0f, 0.0f, -1.0f);
    s.camera.fovY = 40.0f;
    s.materials.push_back(Material{});
    return s;
}

TEST(FocusPick, ASpheresDepthIsTheAnalyticOne) {
    Scene s = lookingDownMinusZ();
    const glm::vec3 c(1.0f, 0.5f, -8.0f);
    const float r = 1.5f;
    s.spheres.push_back(Sphere{c, r, 0, {}});
    const int w = 640, h = 360;
    const SceneGeometry g = buildSceneGeometry(s);
    // The pinhole ray through the sphere's projected centre passes through the centre: it meets the
    // surface at distance |c| - r along the unit direction c / |c|, at depth (|c| - r) · (-c.z / |c|).
    const auto p = projectPoint(s, w, h, c);
    ASSERT_TRUE(p);
    const auto d = focusDistanceAt(s, g, w, h, *p);
    ASSERT_TRUE(d);
    const float L = glm::length(c);
    EXPECT_NEAR(*d, (L - r) * (-c.z / L), 1e-4f);
    EXPECT_LT(*d, L - r) << "depth along the axis, not the distance along the slanted ray";
    // Off the centre: the depth of the analytic hit o + t·u, t = (u·c) − sqrt((u·c)² − |c|² + r²).
    const ImagePoint q{p->x + 20.0f, p->y - 15.0f};
    const glm::vec2 ndc(q.x / float(w) * 2.0f - 1.0f, 1.0f - q.y / float(h) * 2.0f);
    const float tanHalf = std::tan(glm::radians(40.0f) * 0.5f);
    const glm::vec3 u = glm::normalize(glm::vec3(ndc.x * tanHalf * float(w) / float(h), ndc.y * tanHalf, -1.0f));
    const float b = glm::dot(u, c);
    const float t = b - std::sqrt(b * b - glm::dot(c, c) + r * r);
    const auto e = focusDistanceAt(s, g, w, h, q);
    ASSERT_TRUE(e);
    EXPECT_NEAR(*e, t * -u.z, 1e-4f);
}

TEST(FocusPick, ATransformedQuadFacingTheCameraHasTheSameDepthEverywhere) {
    Scene s = lookingDownMinusZ();
    Mesh quad;
    quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    quad.transform.translation = glm::vec3(0.0f, 0.0f, -5.0f);
    quad.transform.scale = glm::vec3(4.0f);
    s.meshes.push_back(quad);
    const SceneGeometry g = buildSceneGeometry(s);
    for (const ImagePoint p : {ImagePoint{320.0f, 180.0f}, ImagePoint{200.5f, 100.5f}, ImagePoint{500.0f, 300.0f}}) {
        const auto d = focusDistanceAt(s, g, 640, 360, p);
        ASSERT_TRUE(d) << p.x << " " << p.y;
        EXPECT_NEAR(*d, 5.0f, 1e-4f);
    }
}

TEST(FocusPick, TheSkyGivesNothing) {
    Scene s = lookingDownMinusZ();
    s.spheres.push_back(Sphere{glm::vec3(0.0f, 0.0f, -8.0f), 1.0f, 0, {}});
    const SceneGeometry g = buildSceneGeometry(s);
    EXPECT_FALSE(focusDistanceAt(s, g, 640, 360, ImagePoint{5.0f, 5.0f}));
}

TEST(FocusPick, TheDefaultScenesWhiteSphereIsFocusedAtItsFrontSurface) {
    const Scene s = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json");
    const SceneGeometry g = buildSceneGeometry(s);
    const auto p = projectPoint(s, 640, 360, s.spheres[1].center);
    const auto d = focusDistanceAt(s, g, 640, 360, *p);
    ASSERT_TRUE(d);
    const glm::vec3 fwd = glm::normalize(s.camera.lookAt - s.camera.position);
    const float centreDepth = glm::dot(s.spheres[1].center - s.camera.position, fwd);
    EXPECT_LT(*d, centreDepth);
    EXPECT_GT(*d, centreDepth - s.spheres[1].radius);
}

} // namespace
} // namespace raylab::ui
