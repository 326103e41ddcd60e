// The estimator on the GPU (OSMesa): analytic scenes where the right answer is known.
#include "render_helpers.h"
#include "support/gl_test.h"
#include "support/statistics.h"

#include <cmath>

using namespace raylab;
using raylab::test::GlTest;

class PathTracerTest : public GlTest {};

TEST_F(PathTracerTest, FurnaceIsExactlyAlbedoTimesSkyInEveryPixel) {
    // A convex Lambertian sphere of albedo ρ under a uniform sky L, filling the view: with cosine
    // sampling every sample is exactly ρ·L (the weight is ρ, the sky L), so any deviation in any
    // pixel, any noise, is a bug. Both entry points.
    const Scene scene = loadScene(test::scenePath("furnace.json"));
    ASSERT_EQ(scene.sky.type, Sky::Type::Constant);
    const glm::vec3 expected = scene.materials[size_t(scene.spheres.at(0).material)].albedo *
                               scene.sky.color * scene.sky.strength;
    for (TracerEntry entry : {TracerEntry::Fragment, TracerEntry::Compute}) {
        const Image image = test::render(scene, {entry, 8, 8, {}});
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(image.rgb(x, y)[c], expected[c], 1e-6f * expected[c])
                        << "pixel " << x << "," << y << " entry " << int(entry);
    }
}

TEST_F(PathTracerTest, ClosedFurnaceConvergesToEmissionOverOneMinusAlbedo) {
    // Inside a closed sphere of albedo a emitting Le everywhere, radiance is Le / (1 − a)
    // (geometric series of bounces). With Russian roulette on, the mean over pixels (independent
    // estimates) must be within 3 standard errors of it.
    // Every sampler: pixels are independent estimates, except zsobol's, which share one sequence
    // and are negatively correlated, so the standard error over pixels overestimates the mean's.
    for (const char* sampler : {"independent", "stratified", "sobol", "zsobol"}) {
        const Scene scene = loadScene(test::scenePath("closed_furnace.json"), {std::string("render.sampler=") + sampler});
        const Material& m = scene.materials[size_t(scene.spheres.at(0).material)];
        ASSERT_LT(scene.render.rrDepth, scene.render.maxBounces) << "the test should exercise roulette";
        const Image image = test::render(scene);
        for (int c = 0; c < 3; ++c) {
            const double expected = m.radiance()[c] / (1.0 - m.albedo[c]);
            const auto values = test::channel(image, c);
            const double se = test::standardError(values);
            EXPECT_GT(se, 0.0);
            EXPECT_NEAR(test::mean(values), expected, 3.0 * se) << sampler << " channel " << c;
            EXPECT_LT(se, 0.01 * expected) << "too noisy to mean anything";
        }
    }
}

TEST_F(PathTracerTest, MaxBouncesTruncatesTheSeriesExactly) {
    // Without roulette the closed furnace is deterministic per bounce count: every path collects
    // Le·(1 + a + … + a^k) for k bounces, exactly, in every pixel.
    for (int bounces : {0, 1, 3}) {
        Scene scene = loadScene(test::scenePath("closed_furnace.json"),
                                {"render.max_bounces=" + std::to_string(bounces), "render.rr_depth=1000",
                                 "render.spp=2"});
        const Material& m = scene.materials[size_t(scene.spheres.at(0).material)];
        const Image image = test::render(scene);
        for (int c = 0; c < 3; ++c) {
            double expected = 0.0, weight = 1.0;
            for (int k = 0; k <= bounces; ++k, weight *= m.albedo[c]) expected += m.radiance()[c] * weight;
            for (double v : test::channel(image, c)) ASSERT_NEAR(v, expected, 1e-5 * expected) << bounces;
        }
    }
}

TEST_F(PathTracerTest, RmseFallsAsOneOverSquareRootOfSamples) {
    // Against a long render with another seed: log–log slope of RMSE over spp must be −0.5 ± 0.1,
    // the rate of independent samples (the stratifying samplers fall faster).
    const std::vector<std::string> small = {"render.width=48", "render.height=27", "render.rpp=4",
                                            "render.sampler=independent"};
    auto with = [&](std::vector<std::string> extra) {
        extra.insert(extra.begin(), small.begin(), small.end());
        return loadScene(test::scenePath("default.json"), extra);
    };
    const Image reference = test::render(with({"render.spp=4096", "render.seed=999"}));
    std::vector<double> logSpp, logRmse;
    for (int spp : {4, 16, 64, 256}) {
        const Image image = test::render(with({"render.spp=" + std::to_string(spp), "render.seed=7"}));
        logSpp.push_back(std::log(double(spp)));
        logRmse.push_back(std::log(test::rmse(image, reference)));
    }
    const double s = test::slope(logSpp, logRmse);
    EXPECT_NEAR(s, -0.5, 0.1) << "RMSE no longer falls as 1/sqrt(spp): bias or correlated samples";
}

TEST_F(PathTracerTest, SameSeedSameImageBitForBitOtherSeedSameMean) {
    const std::vector<std::string> small = {"render.width=40", "render.height=24", "render.spp=16",
                                            "render.rpp=4"};
    auto with = [&](const std::string& seed) {
        auto o = small;
        o.push_back("render.seed=" + seed);
        return loadScene(test::scenePath("default.json"), o);
    };
    const Image a = test::render(with("3"));
    const Image b = test::render(with("3"));
    EXPECT_EQ(a.rgba, b.rgba) << "same scene, settings and seed must reproduce bit for bit";

    const Image c = test::render(with("4"));
    // Other seed: other noise (most pixels differ) but the same expectation. Pixel differences
    // are independent with mean 0; their mean must be within 3.5 standard errors of 0.
    size_t differing = 0;
    std::vector<double> diff;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        differing += a.rgba[i] != c.rgba[i];
        diff.push_back(double(a.rgba[i]) - double(c.rgba[i]));
    }
    EXPECT_GT(double(differing) / double(diff.size()), 0.5);
    EXPECT_NEAR(test::mean(diff), 0.0, 3.5 * test::standardError(diff));
}

TEST_F(PathTracerTest, SplittingSamplesIntoPassesKeepsTheMean) {
    // 16 spp as 16 passes of 1 or 1 pass of 16 uses the same samples: equal up to rounding.
    Scene one = loadScene(test::scenePath("default.json"),
                          {"render.width=32", "render.height=18", "render.spp=16", "render.rpp=1"});
    Scene all = one;
    all.render.rpp = 16;
    const Image a = test::render(one), b = test::render(all);
    for (size_t i = 0; i < a.rgba.size(); ++i)
        ASSERT_NEAR(a.rgba[i], b.rgba[i], 1e-4f * std::max(1.0f, std::abs(b.rgba[i]))) << i;
}

TEST_F(PathTracerTest, NonFiniteSamplesAreCountedAndNeverAccumulated) {
    Scene scene = loadScene(test::scenePath("furnace.json"),
                            {"render.width=16", "render.height=8", "render.spp=10", "render.rpp=5"});
    TracerOptions options;
    options.extraDefines = {{"RAYLAB_INJECT_NONFINITE", "7"}};
    PathTracer tracer(options);
    tracer.setScene(scene);
    renderProgressively(tracer, scene.render);
    // The shader poisons sample k of pixel column x when (k + x) % 7 == 0.
    std::uint64_t expected = 0;
    for (int x = 0; x < 16; ++x)
        for (int k = 0; k < 10; ++k) expected += (k + x) % 7 == 0 ? 8 : 0;
    EXPECT_EQ(tracer.nonFiniteSamples(), expected);
    for (float v : tracer.readImage().rgba) ASSERT_TRUE(std::isfinite(v));
}

TEST_F(PathTracerTest, PinholeProjectionAndPixelJitter) {
    // An emissive sphere of angular radius asin(r/D) on a black sky with no bounces covers
    // tan(asin(r/D)) / tan(fov/2) · H/2 pixels from the centre, vertically and horizontally
    // (square pixels whatever the aspect): 13.35 px at D = 9. Edge pixels are partly covered: jittered samples give
    // fractional values there.
    Scene scene = loadScene(test::scenePath("furnace.json"),
                            {"render.width=128", "render.height=64", "render.spp=64",
                             "render.max_bounces=0", "camera.position=[0,0,9]", "camera.look_at=[0,0,0]",
                             "camera.fov=30", "sky.type=constant", "sky.color=0"});
    scene.materials[size_t(scene.spheres[0].material)].emission = glm::vec3(1.0f);
    scene.materials[size_t(scene.spheres[0].material)].emissionStrength = 1.0f;
    const float r = scene.spheres[0].radius;
    const Image image = test::render(scene);
    const double expectedHalf = std::tan(std::asin(r / 9.0)) / std::tan(glm::radians(15.0)) * 32.0;
    double rowSum = 0.0, columnSum = 0.0;
    int fractional = 0;
    for (int x = 0; x < 128; ++x) {
        const float v = image.rgb(x, 32).g;
        rowSum += v;
        fractional += v > 0.05f && v < 0.95f;
    }
    for (int y = 0; y < 64; ++y) columnSum += 0.5 * (image.rgb(63, y).g + image.rgb(64, y).g);
    // Coverage along a line through the centre = chord length in pixels ≈ 2·expectedHalf.
    EXPECT_NEAR(rowSum, 2.0 * expectedHalf, 1.0);
    EXPECT_NEAR(columnSum, 2.0 * expectedHalf, 1.0);
    EXPECT_GE(fractional, 2) << "no anti-aliased edge pixels: is the pixel jitter gone?";
}

TEST_F(PathTracerTest, GradientSkyTopAndBottom) {
    // No bounces, camera looking straight up (then down): the centre pixel sees the top (bottom)
    // colour of the gradient, the horizon the average of both.
    for (int sign : {1, -1}) {
        Scene scene = loadScene(test::scenePath("furnace.json"),
                                {"render.width=9", "render.height=9", "render.spp=64", "camera.position=[100,50,0]",
                                 "camera.look_at=[100," + std::to_string(50 + sign) + ",0]", "camera.up=[0,0,1]",
                                 "camera.fov=1", "sky.type=gradient", "sky.top=[1,0,0]", "sky.bottom=[0,0,1]",
                                 "sky.strength=2"});
        const Image image = test::render(scene);
        const glm::vec3 centre = image.rgb(4, 4);
        EXPECT_NEAR(centre.r, sign > 0 ? 2.0f : 0.0f, 1e-3f);
        EXPECT_NEAR(centre.b, sign > 0 ? 0.0f : 2.0f, 1e-3f);
    }
}

TEST_F(PathTracerTest, FragmentAndComputeEntryPointsAgree) {
    const Scene scene = loadScene(test::scenePath("default.json"),
                                  {"render.width=37", "render.height=21", "render.spp=4"});
    const Image a = test::render(scene, {TracerEntry::Fragment, 8, 8, {}});
    const Image b = test::render(scene, {TracerEntry::Compute, 8, 8, {}});
    for (size_t i = 0; i < a.rgba.size(); ++i)
        ASSERT_NEAR(a.rgba[i], b.rgba[i], 1e-4f * std::max(1.0f, std::abs(a.rgba[i]))) << i;
}

TEST_F(PathTracerTest, PathRegenerationGivesEachSampleThePlainLoopsRadiance) {
    // The default variant runs a pass's samples as one loop over bounces (path_tracer.glsl, path
    // regeneration); the debug views' variant keeps a loop per sample, and its beauty view traces
    // the same paths. Same pixels, same samples, same sums: the same image bit for bit, at an rpp
    // where regeneration starts samples mid-pass, and with Russian roulette ending paths early.
    const Scene scene = loadScene(test::scenePath("cornell_box.json"), {"render.width=40", "render.height=24",
                                                                        "render.spp=16", "render.rpp=8", "render.rr_depth=1"});
    TracerOptions views;
    views.extraDefines.emplace_back(tracerDefine("RAYLAB_DEBUG_VIEWS"), "1");
    const Image regenerated = test::render(scene);
    const Image plain = test::render(scene, views);
    ASSERT_EQ(regenerated.rgba.size(), plain.rgba.size());
    for (size_t i = 0; i < plain.rgba.size(); ++i) ASSERT_EQ(regenerated.rgba[i], plain.rgba[i]) << i;
    EXPECT_GT(test::mean(test::channel(plain, 0)), 0.01) << "the box is lit";
}
