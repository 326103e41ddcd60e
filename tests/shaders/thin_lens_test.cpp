// The thin-lens camera's maths on the CPU (shaders/include/camera.glsl).
#include "shaders/include/camera.glsl"
#include "shaders/include/random.glsl"
#include "support/statistics.h"

#include <gtest/gtest.h>

using namespace raylab;
using namespace raylab::glsl;

TEST(ShaderThinLens, LensSamplesAreUniformOnTheDiskChiSquare) {
    // Ray origins of the real thin-lens code, in lens coordinates, histogrammed on a 21 × 21 grid
    // over the disk's bounding square; expected counts from each cell's area inside the disk
    // (64 × 64 sub-cells). Cells outside the disk must stay empty. α = 0.01.
    const CameraBasis cam = cameraBasis(vec3(1, 2, 3), vec3(1, 2, -3), vec3(0, 1, 0), 40.0f, 1.5f);
    const float radius = 0.25f;
    const int n = 21, samples = 1000000, sub = 64;
    std::vector<double> observed(n * n, 0.0), expected(n * n, 0.0);
    Rng rng = rngCreate(uvec2(3, 1), 0u, 11u);
    for (int i = 0; i < samples; ++i) {
        const vec2 ndc = 2.0f * rngNext2(rng) - vec2(1.0f);
        const Ray r = cameraRayThinLens(cam, ndc, rngNext2(rng), radius, 5.0f);
        const vec3 d = r.origin - cam.origin;
        const float x = dot(d, cam.right) / radius, y = dot(d, cam.up) / radius;   // in [-1, 1]
        ASSERT_NEAR(dot(d, cam.forward), 0.0f, 1e-6f) << "the lens lies across the view";
        const int cx = std::min(n - 1, int((x + 1.0f) * 0.5f * n));
        const int cy = std::min(n - 1, int((y + 1.0f) * 0.5f * n));
        observed[std::size_t(cy * n + cx)] += 1.0;
    }
    for (int cy = 0; cy < n; ++cy)
        for (int cx = 0; cx < n; ++cx) {
            int inside = 0;
            for (int sy = 0; sy < sub; ++sy)
                for (int sx = 0; sx < sub; ++sx) {
                    const double x = -1.0 + 2.0 * (cx + (sx + 0.5) / sub) / n;
                    const double y = -1.0 + 2.0 * (cy + (sy + 0.5) / sub) / n;
                    inside += x * x + y * y <= 1.0;
                }
            const double cellArea = (2.0 / n) * (2.0 / n) * inside / double(sub * sub);
            expected[std::size_t(cy * n + cx)] = samples * cellArea / PI;
        }
    const test::ChiSquareResult r = test::chiSquareTest(observed, expected);
    EXPECT_FALSE(r.sampleInZeroCell);
    EXPECT_GT(r.pValue, 0.01) << "chi2 " << r.statistic << " dof " << r.dof;
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
