// The thin-lens camera's maths on the CPU (shaders/include/camera.glsl).
#include "shaders/include/camera.glsl"
#include "shaders/include/random.glsl"
#include "support/disk_histogram.h"

#include <gtest/gtest.h>

using namespace raylab;
using namespace raylab::glsl;

TEST(ShaderThinLens, LensSamplesAreUniformOnTheDiskChiSquare) {
    // Ray origins of the real thin-lens code, in lens coordinates, histogrammed on a 21 × 21 grid
    // over the disk's bounding square (support/disk_histogram.h). Cells outside the disk must stay
    // empty. α = 0.01. The same test of the shader on the GPU: GpuSamplingTest.LensDisk*.
    const CameraBasis cam = cameraBasis(vec3(1, 2, 3), vec3(1, 2, -3), vec3(0, 1, 0), 40.0f, 1.5f);
    const float radius = 0.25f;
    const int samples = 1000000;
    test::DiskHistogram disk;
    Rng rng = rngCreate(uvec2(3, 1), 0u, 11u);
    for (int i = 0; i < samples; ++i) {
        const vec2 ndc = 2.0f * rngNext2(rng) - vec2(1.0f);
        const Ray r = cameraRayThinLens(cam, ndc, rngNext2(rng), radius, 5.0f);
        const vec3 d = r.origin - cam.origin;
        ASSERT_NEAR(dot(d, cam.forward), 0.0f, 1e-6f) << "the lens lies across the view";
        disk.add(dot(d, cam.right) / radius, dot(d, cam.up) / radius);
    }
    const test::ChiSquareResult r = disk.chiSquare();
    EXPECT_FALSE(r.sampleInZeroCell);
    EXPECT_GT(r.pValue, 0.01) << "chi2 " << r.statistic << " dof " << r.dof;
}

TEST(ShaderThinLens, DiskChiSquareRejectsTheNaivePolarMap) {
    // The test must be able to fail: r = u1, θ = 2π·u2 crowds the centre (pdf 1 / (2π r)).
    test::DiskHistogram disk;
    Rng rng = rngCreate(uvec2(4, 1), 0u, 12u);
    for (int i = 0; i < 1000000; ++i) {
        const vec2 u = rngNext2(rng);
        disk.add(u.x * std::cos(2.0f * PI * u.y), u.x * std::sin(2.0f * PI * u.y));
    }
    EXPECT_LT(disk.chiSquare().pValue, 1e-6);
}

TEST(ShaderThinLens, RaysThroughAPixelMeetOnTheFocusPlaneAndZeroApertureIsThePinhole) {
    const CameraBasis cam = cameraBasis(vec3(0, 1, 6), vec3(0, 1, 0), vec3(0, 1, 0), 40.0f, 16.0f / 9.0f);
    Rng rng = rngCreate(uvec2(5, 5), 0u, 5u);
    for (int i = 0; i < 1000; ++i) {
        const vec2 ndc = 2.0f * rngNext2(rng) - vec2(1.0f);
        const Ray pin = cameraRay(cam, ndc);
        const Ray pin0 = cameraRayThinLens(cam, ndc, rngNext2(rng), 0.0f, 3.0f);
        EXPECT_EQ(pin0.origin, pin.origin);
        EXPECT_NEAR(length(pin0.dir - pin.dir), 0.0f, 1e-6f);
        // Where a lens ray crosses the plane 3 units ahead equals where the pinhole ray does.
        const Ray lens = cameraRayThinLens(cam, ndc, rngNext2(rng), 0.5f, 3.0f);
        const float tl = (3.0f - dot(lens.origin - cam.origin, cam.forward)) / dot(lens.dir, cam.forward);
        const float tp = 3.0f / dot(pin.dir, cam.forward);
        EXPECT_NEAR(length(rayAt(lens, tl) - rayAt(pin, tp)), 0.0f, 1e-5f);
    }
}
