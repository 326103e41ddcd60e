// Camera-relative precision: a scene moved 10^5 units from the origin renders as it does at the
// origin, because the host subtracts the camera's position (in double) before upload.
#include "render/camera_relative.h"
#include "render_helpers.h"
#include "support/batch_stats.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace raylab;

namespace {

// Spheres, a ground, an emissive sphere and an emissive quad (a mesh placed by its transform), lit
// by NEE; every coordinate a multiple of 1/64, so the moved scene holds exactly the same shapes.
constexpr const char* kScene = R"({
  "camera": {"position": [0.5, 1.5, 5.0], "look_at": [0.0, 0.75, 0.0], "fov": 40},
  "render": {"width": 16, "height": 16, "spp": 16, "rpp": 16, "max_bounces": 4, "nee": true},
  "sky": {"type": "gradient", "top": [0.3, 0.4, 0.6], "bottom": [0.1, 0.1, 0.1]},
  "materials": {"grey": {"albedo": 0.6}, "red": {"albedo": [0.8, 0.2, 0.1], "f0": 0.04, "roughness": 0.3},
                "lamp": {"albedo": 0, "emission": [1, 0.9, 0.7], "strength": 6}},
  "objects": [
    {"type": "sphere", "radius": 100, "material": "grey", "transform": {"translation": [0, -100, 0]}},
    {"type": "sphere", "radius": 0.75, "material": "red", "transform": {"translation": [-0.5, 0.75, 0]}},
    {"type": "sphere", "radius": 0.25, "material": "lamp", "transform": {"translation": [1.25, 0.5, 0.5]}},
    {"type": "mesh", "material": "lamp", "positions": [-0.5, 0, -0.5, 0.5, 0, -0.5, 0.5, 0, 0.5, -0.5, 0, 0.5],
     "indices": [0, 1, 2, 0, 2, 3], "transform": {"translation": [0.25, 2.5, 0.25]}}
  ]
})";

std::string vec(double x, double y, double z) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "[%.17g, %.17g, %.17g]", x, y, z);
    return buf;
}

// The scene with every object and the camera moved by `shift`, through --set keys.
Scene movedBy(glm::dvec3 shift) {
    const Scene base = parseScene(kScene, "relative.json");
    std::vector<std::string> overrides;
    const auto moved = [&](glm::vec3 p) { return vec(p.x + shift.x, p.y + shift.y, p.z + shift.z); };
    overrides.push_back("camera.position=" + moved(base.camera.position));
    overrides.push_back("camera.look_at=" + moved(base.camera.lookAt));
    for (std::size_t i = 0; i < base.spheres.size(); ++i)
        overrides.push_back("objects." + std::to_string(i) + ".transform.translation=" + moved(base.spheres[i].transform.translation));
    for (std::size_t i = 0; i < base.meshes.size(); ++i)
        overrides.push_back("objects." + std::to_string(base.spheres.size() + i) +
                            ".transform.translation=" + moved(base.meshes[i].transform.translation));
    return parseScene(kScene, "relative.json", overrides);
}

double imageMean(const test::BatchStats& s) {
    double sum = 0.0;
    for (std::size_t i = 0; i < s.mean.size(); ++i)
        if (i % 4 != 3) sum += s.mean[i];
    return sum / double(s.mean.size() / 4 * 3);
}

test::BatchStats batches(const Scene& scene, bool cameraRelative) {
    TracerOptions o;
    o.cameraRelative = cameraRelative;
    return test::renderBatches(scene, 16, o);
}

} // namespace

class CameraRelativeTest : public test::GlTest {};

TEST(CameraRelative, SubtractsInDoubleAndFoldsSphereTransforms) {
    Scene s = movedBy({1e5, 0.0, -1e5});
    s.spheres[1].center = glm::vec3(0.5f, 0.0f, 0.0f);
    s.spheres[1].transform.scale = glm::vec3(2.0f);
    const glm::dvec3 origin(s.camera.position);
    const Scene r = cameraRelative(s, origin);
    EXPECT_EQ(r.camera.position, glm::vec3(0.0f));
    EXPECT_EQ(r.camera.lookAt, glm::vec3(-0.5f, -0.75f, -5.0f));
    EXPECT_EQ(r.spheres[0].center, glm::vec3(-0.5f, -101.5f, -5.0f));
    EXPECT_EQ(r.spheres[1].center, glm::vec3(0.0f, -0.75f, -5.0f)) << "translation + scale · centre, then − origin";
    EXPECT_EQ(r.spheres[1].radius, 1.5f);
    EXPECT_EQ(r.spheres[1].transform, Transform{});
    EXPECT_EQ(r.meshes[0].transform.translation, glm::vec3(-0.25f, 1.0f, -4.75f));
    EXPECT_EQ(r.meshes[0].positions, s.meshes[0].positions) << "meshes stay in object space";
    EXPECT_FALSE(needsRebase(s.camera, origin));
    Camera far = s.camera;
    far.position += glm::vec3(100.0f, 0.0f, 0.0f);
    far.lookAt += glm::vec3(100.0f, 0.0f, 0.0f);
    EXPECT_TRUE(needsRebase(far, origin)) << "20 viewing distances away";
}

// 16 batches (seeds) of 16 spp each, 16×16 pixels. Per-pixel z-test at α = 0.01, Šidák over pixels
// and channels: every pixel must agree, and the image means within 0.5 %. The test can fail: the
// same scene traced in world coordinates (float32 spacing 1/128 at 10^5) must break it.
TEST_F(CameraRelativeTest, ASceneMovedTenToTheFiveRendersAsAtTheOrigin) {
    const test::BatchStats home = batches(movedBy({0.0, 0.0, 0.0}), true);
    const test::BatchStats far = batches(movedBy({1e5, 1e5, -1e5}), true);
    const double homeMean = imageMean(home), farMean = imageMean(far);
    EXPECT_NEAR(farMean / homeMean, 1.0, 0.005) << homeMean << " vs " << farMean;
    EXPECT_EQ(test::fractionAgreeing(home, far), 1.0);

    const test::BatchStats world = batches(movedBy({1e5, 1e5, -1e5}), false);
    const double worldMean = imageMean(world);
    std::printf("image mean: at the origin %.5f, moved 1e5 %.5f, moved 1e5 in world coordinates %.5f (%.3f of pixels agree)\n",
                homeMean, farMean, worldMean, test::fractionAgreeing(home, world));
    EXPECT_TRUE(std::abs(worldMean / homeMean - 1.0) > 0.005 || test::fractionAgreeing(home, world) < 1.0)
        << "the negative control: world coordinates at 10^5 must show";
}

// A camera drag within its region keeps the uploaded scene; leaving it moves the origin with one
// top-level upload, and the image stays the one of a fresh upload.
TEST_F(CameraRelativeTest, TheOriginFollowsACameraThatLeavesItsRegion) {
    Scene s = movedBy({1e5, 0.0, 0.0});
    s.render.spp = 4;
    s.render.rpp = 4;
    PathTracer tracer;
    tracer.setScene(s);
    const std::uint64_t updates = tracer.gpuScene().topLevelUpdates();
    s.camera.fovY = 30.0f;
    s.camera.position.x += 1.0f;
    tracer.updateSettings(s);
    EXPECT_EQ(tracer.gpuScene().topLevelUpdates(), updates) << "a small move keeps the origin";
    EXPECT_EQ(tracer.origin().x, 1e5 + 0.5);
    s.camera.position.z += 200.0f;
    s.camera.lookAt.z += 200.0f;
    tracer.updateSettings(s);
    EXPECT_EQ(tracer.gpuScene().topLevelUpdates(), updates + 1);
    EXPECT_EQ(tracer.origin(), glm::dvec3(s.camera.position));
    renderProgressively(tracer, s.render);
    const Image moved = tracer.readImage();
    PathTracer fresh;
    fresh.setScene(s);
    renderProgressively(fresh, s.render);
    const Image direct = fresh.readImage();
    EXPECT_EQ(moved.rgba, direct.rgba);
}
