// Depth of field on the GPU: a plane at the focus distance is as sharp as with a pinhole; a
// uniform environment does not care about the aperture.
#include "render_helpers.h"
#include "support/gl_test.h"

using namespace raylab;

namespace {

// Emissive stripes on a plane 4 units ahead (max_bounces 0: the image is the emission pattern).
std::string stripes(const std::string& camera) {
    std::string objects;
    for (int i = 0; i < 8; ++i) {
        const float x0 = -2.0f + 0.5f * float(i), x1 = x0 + 0.5f;
        objects += std::string(i ? "," : "") + R"({ "type": "mesh", "material": ")" + (i % 2 ? "on" : "off") +
                   R"(", "positions": [)" + std::to_string(x0) + ",-2,0, " + std::to_string(x1) + ",-2,0, " +
                   std::to_string(x1) + ",2,0, " + std::to_string(x0) + R"(,2,0], "indices": [0,1,2, 0,2,3] })";
    }
    return R"({ "camera": { "position": [0, 0, 4], "look_at": [0, 0, 0], "fov": 30, )" + camera +
           R"( }, "render": { "width": 32, "height": 32, "spp": 64, "max_bounces": 0, "tone_map": "clamp" },
      "sky": { "type": "constant", "color": 0 },
      "materials": { "on": { "albedo": 0, "emission": 1, "strength": 1 }, "off": { "albedo": 0 } },
      "objects": [ )" + objects + " ] }";
}

} // namespace

class ThinLensRenderTest : public test::GlTest {};

TEST_F(ThinLensRenderTest, PlaneAtTheFocusDistanceMatchesThePinhole) {
    const Image pinhole = test::render(parseScene(stripes(R"("aperture": 0)"), "pin.json"));
    const Image pinhole2 = test::render(parseScene(stripes(R"("aperture": 0)"), "pin.json", {"render.seed=2"}));
    const Image focused = test::render(parseScene(stripes(R"("aperture": 0.3, "focus_distance": 4)"), "f.json"));
    const Image defaultFocus = test::render(parseScene(stripes(R"("aperture": 0.3)"), "f0.json"));
    const Image blurred = test::render(parseScene(stripes(R"("aperture": 0.3, "focus_distance": 1.5)"), "b.json"));
    // Noise between two pinhole renders (pixel jitter across stripe edges) sets the scale.
    const double noise = test::rmse(pinhole, pinhole2);
    EXPECT_GT(noise, 0.0);
    // In focus: differs from the pinhole only by noise (independent renders: same RMSE scale;
    // 1.5× allows for the sampling spread of the RMSE of 1024 pixels at 64 spp).
    EXPECT_LT(test::rmse(focused, pinhole), 1.5 * noise);
    EXPECT_LT(test::rmse(defaultFocus, pinhole), 1.5 * noise) << "focus_distance 0 focuses on look_at";
    // Out of focus the stripes blur: far more than noise.
    EXPECT_GT(test::rmse(blurred, pinhole), 5.0 * noise);
}

TEST_F(ThinLensRenderTest, UniformEnvironmentDoesNotChangeWithAperture) {
    for (const char* aperture : {"0", "0.1", "2"}) {
        // The only object is behind the camera and never seen.
        const Scene scene = parseScene(std::string(R"({ "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1],
            "aperture": )") + aperture + R"(, "focus_distance": 3 }, "render": { "width": 16, "height": 16, "spp": 4 },
            "sky": { "type": "constant", "color": 0.7 }, "objects": [ { "center": [0, 0, 50], "radius": 1 } ] })",
                                       "env.json");
        const Image image = test::render(scene);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) ASSERT_NEAR(image.rgb(x, y)[1], 0.7f, 1e-6f) << aperture;
    }
}
