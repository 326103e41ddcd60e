// llvmpipe ends every loop of a shader invocation once 65535 loop iterations have run in all
// (gallivm's loop limiter). A pass of many samples must not lose light to it: the tracer splits a
// pass into draws of a few samples, and counts the draws the driver still cut short.
#include "render/shader_variant.h"
#include "render_helpers.h"
#include "support/gl_test.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

using namespace raylab;

namespace {

// Largest difference, relative to the value (at least 1e-3 absolute), over every channel.
double largestRelativeDifference(const Image& a, const Image& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = std::abs(double(a.rgba[i]) - double(b.rgba[i]));
        worst = std::max(worst, d / std::max(1e-3, std::abs(double(b.rgba[i]))));
    }
    return worst;
}

bool onLlvmpipe() {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return renderer != nullptr && std::strstr(renderer, "llvmpipe") != nullptr;
}

// A closed box of triangles around the camera whose walls glow and reflect 99.9 %: with roulette
// off, every path makes all 512 bounces, each a loop over the mesh's 12 triangles, so a draw of 16
// samples runs out of the driver's loop budget (16 × 512 × 12 > 65535).
constexpr const char* kClosedBox = R"({
  "camera": {"position": [0, 0, 0], "look_at": [0, 0, 1], "fov": 60},
  "render": {"width": 8, "height": 8, "rpp": 16, "spp": 32, "max_bounces": 512, "rr_depth": 512,
             "nee": false, "sampler": "independent"},
  "sky": {"type": "constant", "color": 0},
  "materials": {"wall": {"albedo": 0.999, "emission": 1, "strength": 0.001}},
  "objects": [{"type": "mesh", "material": "wall",
    "positions": [-1,-1,-1, 1,-1,-1, 1,1,-1, -1,1,-1, -1,-1,1, 1,-1,1, 1,1,1, -1,1,1],
    "indices": [0,1,2, 0,2,3, 4,6,5, 4,7,6, 0,4,5, 0,5,1, 3,2,6, 3,6,7, 0,3,7, 0,7,4, 1,5,6, 1,6,2]}]
})";

} // namespace

class LoopLimitTest : public test::GlTest {};

// The Cornell box (every ray a loop over its objects and their triangles) at 1024 spp: one pass of
// 1024 samples and 1024 passes of one take the same samples (every pixel every pass:
// render.adaptive false), so the means agree to float rounding. Its loops have bounded trips, so a
// draw takes as many samples as half the budget allows (boundedLoopIterationsPerSample), more than
// kSamplesPerDraw, and with every sampler, zsobol's digit loop and stratified's walk included, no
// invocation runs out. Before the split, the pass of 1024 lost 88 % of the image's light.
TEST_F(LoopLimitTest, APassOfManySamplesEqualsThePassesOfOneEach) {
    for (const char* sampler : {"independent", "stratified", "sobol", "zsobol"}) {
        const Scene scene = loadScene(test::scenePath("cornell_box.json"),
                                      {"render.width=16", "render.height=16", "render.adaptive=false",
                                       std::string("render.sampler=") + sampler});
        PathTracer onePass, manyPasses;
        onePass.setScene(scene);
        manyPasses.setScene(scene);
        onePass.renderPass(1024);
        for (int i = 0; i < 1024; ++i) manyPasses.renderPass(1);
        EXPECT_LT(largestRelativeDifference(onePass.readImage(), manyPasses.readImage()), 1e-4) << sampler;
        EXPECT_EQ(onePass.loopLimitedInvocations(), 0u) << sampler;
        const std::uint64_t bound = boundedLoopIterationsPerSample(scene, sceneFeatures(scene), false);
        ASSERT_GT(bound, 0u) << sampler;
        EXPECT_EQ(onePass.samplesPerDraw(),
                  int(std::min<std::uint64_t>(kLoopIterationBudget / 2 / bound, PathTracer::kBoundedSamplesPerDraw)))
            << sampler;
        EXPECT_GT(onePass.samplesPerDraw(), PathTracer::kSamplesPerDraw) << sampler;
    }
}

// Where even a draw of 16 samples runs out, the shader's count says so and later draws take fewer:
// the unspecialised tracer, whose BVH walks have no bound. The scene's own variant (one small mesh)
// has one, and sizes its draws by it from the start.
TEST_F(LoopLimitTest, ADrawTheDriverCutsShortIsCountedAndLaterDrawsTakeFewerSamples) {
    if (!onLlvmpipe()) GTEST_SKIP() << "only llvmpipe limits loop iterations";
    const Scene scene = parseScene(kClosedBox, "closed_box.json");
    PathTracer bounded;
    bounded.setScene(scene);
    bounded.renderPass(16);
    EXPECT_EQ(bounded.loopLimitedInvocations(), 0u);
    EXPECT_EQ(bounded.samplesPerDraw(), 2) << "32767 / ((1 + 12) · 1026 + 513)";

    TracerOptions unspecialised;
    unspecialised.specialise = false;
    PathTracer tracer(unspecialised);
    tracer.setScene(scene);
    tracer.renderPass(16);
    EXPECT_GT(tracer.loopLimitedInvocations(), 0u);
    EXPECT_LT(tracer.samplesPerDraw(), PathTracer::kSamplesPerDraw);
    // With few enough samples per draw no invocation runs out.
    while (tracer.loopLimitedInvocations() > 0 && tracer.samplesPerDraw() > 1) {
        tracer.reset();
        tracer.renderPass(16);
    }
    EXPECT_EQ(tracer.loopLimitedInvocations(), 0u) << "at " << tracer.samplesPerDraw() << " samples per draw";
    tracer.reset();
    EXPECT_EQ(tracer.loopLimitedInvocations(), 0u) << "reset clears the count";
}
