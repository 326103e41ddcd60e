#include "app/camera_control.h"

#include <gtest/gtest.h>

namespace raylab::ui {
namespace {

TEST(CameraControl, OrbitKeepsTheDistanceAndTheLookAtPoint) {
    Camera c;
    c.position = {6.0f, 3.0f, 8.0f};
    c.lookAt = {0.0f, 1.0f, 0.0f};
    const float d = glm::length(c.position - c.lookAt);
    orbitCamera(c, 0.7f, 0.2f);
    EXPECT_NEAR(glm::length(c.position - c.lookAt), d, 1e-4f);
    EXPECT_EQ(c.lookAt, glm::vec3(0.0f, 1.0f, 0.0f));
    orbitCamera(c, 0.0f, 10.0f);   // pitch stops before the pole
    const glm::vec3 v = glm::normalize(c.position - c.lookAt);
    EXPECT_LT(v.y, 0.9999f);
    EXPECT_GT(v.y, 0.99f);
}

TEST(CameraControl, TurnKeepsTheEyeAndMoveKeepsTheViewDirection) {
    Camera c;
    const glm::vec3 eye = c.position;
    turnCamera(c, 0.5f, -0.1f);
    EXPECT_EQ(c.position, eye);
    const glm::vec3 dir = glm::normalize(c.lookAt - c.position);
    moveCamera(c, 2.0f, 1.0f, 0.5f);
    EXPECT_NEAR(glm::length(glm::normalize(c.lookAt - c.position) - dir), 0.0f, 1e-5f);
    // forward 2 along dir, up 0.5, right 1 perpendicular to both
    const glm::vec3 moved = c.position - eye;
    EXPECT_NEAR(glm::dot(moved, dir), 2.0f + 0.5f * dir.y, 1e-4f);
}

TEST(CameraControl, ForwardMovesTowardTheLookAtPoint) {
    Camera c;   // eye (0,1,6) looking at (0,1,0)
    moveCamera(c, 1.0f, 0.0f, 0.0f);
    EXPECT_NEAR(c.position.z, 5.0f, 1e-5f);
    moveCamera(c, 0.0f, 1.0f, 0.0f);   // right is +x for this camera
    EXPECT_NEAR(c.position.x, 1.0f, 1e-5f);
    dollyCamera(c, 0.5f);
    EXPECT_NEAR(glm::length(c.position - c.lookAt), 3.0f, 1e-4f);
}

} // namespace
} // namespace raylab::ui
