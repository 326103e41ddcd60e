#include "shaders/include/camera.glsl"

#include <gtest/gtest.h>

using namespace raylab::glsl;

TEST(ShaderCamera, CentreAndCornersFollowTheFieldOfView) {
    const CameraBasis cam = cameraBasis(vec3(1, 2, 3), vec3(1, 2, -7), vec3(0, 1, 0), 60.0f, 2.0f);
    const Ray centre = cameraRay(cam, vec2(0.0f));
    EXPECT_NEAR(glm::length(centre.dir - vec3(0, 0, -1)), 0.0f, 1e-6f);
    EXPECT_EQ(centre.origin, vec3(1, 2, 3));
    // Top edge centre: tan(angle to the axis) = tan(fov/2).
    const Ray top = cameraRay(cam, vec2(0.0f, 1.0f));
    EXPECT_NEAR(top.dir.y / -top.dir.z, std::tan(glm::radians(30.0f)), 1e-5f);
    // Right edge: the aspect ratio widens the horizontal extent.
    const Ray right = cameraRay(cam, vec2(1.0f, 0.0f));
    EXPECT_NEAR(right.dir.x / -right.dir.z, 2.0f * std::tan(glm::radians(30.0f)), 1e-5f);
    EXPECT_GT(right.dir.x, 0.0f);   // image +x is world +x when looking down -z with y up
}
