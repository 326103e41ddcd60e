// The light gizmos' image-space lines: a light in front of the camera lands on the pixel the
// tracer's camera puts it on, a spot draws its outer cone, a sun an arrow from the image centre,
// and what lies behind the camera draws nothing.
#include "app/light_gizmo.h"

#include "scene/scene_loader.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace raylab::ui {
namespace {

constexpr int kW = 200, kH = 100;

// The eye on +z looking at the origin, 40 degrees vertical field of view.
Scene sceneWith(Light light) {
    Scene s = parseScene(R"({"camera": {"position": [0, 0, 10], "look_at": [0, 0, 0], "fov": 40},
        "materials": {"white": {"albedo": 0.8}},
        "objects": [{"type": "sphere", "center": [0, -101, 0], "radius": 100, "material": "white"}]})",
                         "gizmo.json");
    s.lights.push_back(light);
    return s;
}

Light light(Light::Type type, glm::vec3 position, glm::vec3 direction = glm::vec3(0, -1, 0)) {
    Light l;
    l.type = type;
    l.position = position;
    l.direction = direction;
    return l;
}

glm::vec2 mid(const Segment& s) { return {0.5f * (s.a.x + s.b.x), 0.5f * (s.a.y + s.b.y)}; }

TEST(LightGizmo, APointLightIsAStarOnItsPixel) {
    // Half-way up the view's half-height at the origin's depth: a quarter of the image from the top.
    const float y = 10.0f * std::tan(glm::radians(20.0f)) * 0.5f;
    const std::vector<Segment> g = lightGizmo(sceneWith(light(Light::Type::Point, {0, y, 0})), kW, kH, 0);
    ASSERT_EQ(g.size(), 4u);
    for (const Segment& s : g) {
        EXPECT_NEAR(mid(s).x, 100.0f, 1e-3f);
        EXPECT_NEAR(mid(s).y, 25.0f, 1e-3f);
    }
    const float r = std::max(3.0f, kGizmoSizeOfHeight * float(kH));
    EXPECT_NEAR(g[0].a.x, 100.0f - r, 1e-3f);
    EXPECT_NEAR(g[0].b.x, 100.0f + r, 1e-3f);
    EXPECT_TRUE(lightGizmo(sceneWith(light(Light::Type::Point, {0, y, 0})), kW, kH, 1).empty()) << "no light 1";
}

TEST(LightGizmo, ALightBehindTheCameraDrawsNothing) {
    EXPECT_TRUE(lightGizmo(sceneWith(light(Light::Type::Point, {0, 0, 12})), kW, kH, 0).empty());
    // A spot behind the eye that points away from the scene: its whole cone is behind too.
    EXPECT_TRUE(lightGizmo(sceneWith(light(Light::Type::Spot, {0, 0, 12}, {0, 0, 1})), kW, kH, 0).empty());
}

TEST(LightGizmo, ASpotDrawsItsOuterConeFromItsApex) {
    Light spot = light(Light::Type::Spot, {0, 0, 0}, {0, -1, 0});
    spot.outerAngle = 30.0f;
    const Scene scene = sceneWith(spot);
    const std::vector<Segment> g = lightGizmo(scene, kW, kH, 0);
    ASSERT_EQ(g.size(), std::size_t(4 + kGizmoCircleSegments + 4));
    // The rim: a circle of radius L tan(outer) at L = a third of the distance to the eye, below the apex.
    const float L = 10.0f / 3.0f, R = L * std::tan(glm::radians(30.0f));
    const auto left = projectPoint(scene, kW, kH, {-R, -L, 0}), right = projectPoint(scene, kW, kH, {R, -L, 0});
    ASSERT_TRUE(left && right);
    float lo = 1e9f, hi = -1e9f;
    for (std::size_t i = 4; i < 4 + kGizmoCircleSegments; ++i) {
        lo = std::min({lo, g[i].a.x, g[i].b.x});
        hi = std::max({hi, g[i].a.x, g[i].b.x});
        EXPECT_GT(g[i].a.y, 50.0f) << "the rim lies below the apex";
    }
    EXPECT_NEAR(lo, left->x, 1e-2f);
    EXPECT_NEAR(hi, right->x, 1e-2f);
    // The cone's sides run from the apex (the image centre) to the rim.
    for (std::size_t i = 4 + kGizmoCircleSegments; i < g.size(); ++i) {
        EXPECT_NEAR(g[i].a.x, 100.0f, 1e-3f);
        EXPECT_NEAR(g[i].a.y, 50.0f, 1e-3f);
        EXPECT_GT(g[i].b.y, 50.0f);
    }
    // A wider cone draws a wider rim.
    spot.outerAngle = 60.0f;
    const std::vector<Segment> wide = lightGizmo(sceneWith(spot), kW, kH, 0);
    float wideHi = -1e9f;
    for (std::size_t i = 4; i < 4 + kGizmoCircleSegments; ++i) wideHi = std::max({wideHi, wide[i].a.x, wide[i].b.x});
    EXPECT_GT(wideHi, hi + 5.0f);
}

TEST(LightGizmo, ASunIsAnArrowFromTheImageCentre) {
    // Light travelling to the right: a circle at the centre and an arrow whose tip is right of it.
    const std::vector<Segment> g = lightGizmo(sceneWith(light(Light::Type::Distant, {}, {1, 0, 0})), kW, kH, 0);
    ASSERT_EQ(g.size(), std::size_t(kGizmoCircleSegments + 3));
    const Segment& shaft = g[kGizmoCircleSegments];
    EXPECT_GT(shaft.b.x, 120.0f);
    EXPECT_NEAR(shaft.b.y, 50.0f, 1e-3f);
    EXPECT_NEAR(shaft.a.y, 50.0f, 1e-3f);
    for (std::size_t i = 0; i < std::size_t(kGizmoCircleSegments); ++i) {
        EXPECT_NEAR(std::hypot(g[i].a.x - 100.0f, g[i].a.y - 50.0f), std::max(3.0f, kGizmoSizeOfHeight * kH), 1e-3f);
    }
    // Along the view axis: the circle alone.
    EXPECT_EQ(lightGizmo(sceneWith(light(Light::Type::Distant, {}, {0, 0, -1})), kW, kH, 0).size(),
              std::size_t(kGizmoCircleSegments));
}

} // namespace
} // namespace raylab::ui
