// Stop conditions of the progressive driver: target spp, time budget, stop flag.
#include "render_helpers.h"
#include "support/gl_test.h"

using namespace raylab;

class ProgressiveRenderTest : public test::GlTest {};

TEST_F(ProgressiveRenderTest, StopsExactlyAtTheTargetWithAShortLastPass) {
    Scene scene = loadScene(test::scenePath("furnace.json"),
                            {"render.width=8", "render.height=8", "render.spp=10", "render.rpp=4"});
    PathTracer tracer;
    tracer.setScene(scene);
    int calls = 0;
    const RenderOutcome o = renderProgressively(tracer, scene.render, nullptr, [&](const RenderProgress& p) {
        ++calls;
        EXPECT_EQ(p.targetSpp, 10u);
    });
    EXPECT_EQ(tracer.samplesPerPixel(), 10u);   // 4 + 4 + 2
    EXPECT_EQ(tracer.passes(), 3u);
    EXPECT_EQ(calls, 3);
    EXPECT_FALSE(o.interrupted);
    EXPECT_EQ(o.last.eta, 0.0);
}

TEST_F(ProgressiveRenderTest, TimeBudgetStopsLongBeforeAnUnreachableTarget) {
    Scene scene = loadScene(test::scenePath("default.json"),
                            {"render.width=32", "render.height=18", "render.spp=100000000", "render.time=0.3"});
    PathTracer tracer;
    tracer.setScene(scene);
    const RenderOutcome o = renderProgressively(tracer, scene.render);
    EXPECT_GE(o.last.elapsed, 0.3);
    EXPECT_GT(tracer.samplesPerPixel(), 0u);
    EXPECT_LT(tracer.samplesPerPixel(), 100000000u);
    EXPECT_FALSE(o.interrupted);
}

TEST_F(ProgressiveRenderTest, StopFlagEndsBetweenPasses) {
    Scene scene = loadScene(test::scenePath("furnace.json"),
                            {"render.width=8", "render.height=8", "render.spp=1000", "render.rpp=1"});
    PathTracer tracer;
    tracer.setScene(scene);
    std::atomic<bool> stop{false};
    const RenderOutcome o = renderProgressively(tracer, scene.render, &stop, [&](const RenderProgress& p) {
        if (p.spp == 5) stop = true;
    });
    EXPECT_TRUE(o.interrupted);
    EXPECT_EQ(tracer.samplesPerPixel(), 5u);
}
