// The equirectangular mapping shared by the shader and the tools.
#include "shaders/include/environment_map.glsl"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab::glsl;

TEST(ShaderEnvironmentMap, OrientationOfTheImage) {
    // Image centre straight ahead (−z), top row up, +x a quarter turn to the right of the centre.
    EXPECT_NEAR(equirectFromDirection(vec3(0, 0, -1), 0.0f).x, 0.5f, 1e-6f);
    EXPECT_NEAR(equirectFromDirection(vec3(0, 0, -1), 0.0f).y, 0.5f, 1e-6f);
    EXPECT_NEAR(equirectFromDirection(vec3(1, 0, 0), 0.0f).x, 0.75f, 1e-6f);
    EXPECT_NEAR(equirectFromDirection(vec3(-1, 0, 0), 0.0f).x, 0.25f, 1e-6f);
    EXPECT_NEAR(equirectFromDirection(vec3(0, 1, 0), 0.0f).y, 0.0f, 1e-6f);
    EXPECT_NEAR(equirectFromDirection(vec3(0, -1, 0), 0.0f).y, 1.0f, 1e-6f);
    // A positive rotation brings what was at +x to the front.
    EXPECT_NEAR(equirectFromDirection(vec3(0, 0, -1), PI / 2).x, 0.75f, 1e-6f);
}

TEST(ShaderEnvironmentMap, RoundTripAndRange) {
    for (float rot : {0.0f, 1.0f, -2.5f, 6.0f})
        for (int i = 0; i < 50; ++i)
            for (int j = 1; j < 50; ++j) {
                const vec2 uv((float(i) + 0.5f) / 50.0f, float(j) / 50.0f);
                const vec3 d = directionFromEquirect(uv, rot);
                ASSERT_NEAR(glm::length(d), 1.0f, 1e-5f);
                const vec2 back = equirectFromDirection(d, rot);
                ASSERT_GE(back.x, 0.0f);
                ASSERT_LT(back.x, 1.0f);
                const float du = std::abs(back.x - uv.x);
                ASSERT_LT(std::min(du, 1.0f - du), 1e-4f) << uv.x << " " << uv.y << " rot " << rot;
                ASSERT_NEAR(back.y, uv.y, 1e-4f);
            }
}
