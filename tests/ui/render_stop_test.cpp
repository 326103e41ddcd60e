// The Render panel's stops: tracing ends at the target samples per pixel (render.spp) or when the
// time budget (render.time) is spent, whichever comes first; the Stats panel says so (ImGui
// frames without a window, support/panel_frame_test.h). Passes are cut into bands by a tiny frame
// budget, so a stop could land in the middle of a pass.
#include "support/panel_frame_test.h"

#include <gtest/gtest.h>

#include <string>

namespace raylab::ui {
namespace {

class RenderStopTest : public test::PanelFrameTest {
protected:
    // Traces as the window loop does, with a frame budget so small that every unit is a band.
    void traceUntilConverged() {
        for (int i = 0; i < 1000000 && !viewer->converged(); ++i) viewer->update(1e-5);
        ASSERT_TRUE(viewer->converged());
    }
    std::uint64_t spp() const { return viewer->tracer()->samplesPerPixel(); }
    // Tracing more does nothing once converged.
    void expectStopped() {
        const std::uint64_t before = spp();
        const double seconds = viewer->stats().traceSeconds;
        for (int i = 0; i < 5; ++i) viewer->update(0.01);
        EXPECT_EQ(spp(), before);
        EXPECT_EQ(viewer->stats().traceSeconds, seconds);
    }
};

TEST_F(RenderStopTest, StopsAtTheTargetSppExactly) {
    ASSERT_TRUE(viewer->document().set("render.rpp", "3"));
    ASSERT_TRUE(viewer->document().set("render.spp", "7"));   // passes of 3, 3 and a last one of 1
    traceUntilConverged();
    EXPECT_EQ(spp(), 7u);
    EXPECT_EQ(viewer->tracer()->passes(), 3u);
    expectStopped();
    const std::string text = windowText([&] { drawStatsPanel(*viewer, ui); });
    EXPECT_NE(text.find("7 spp of 7 (done)"), std::string::npos) << text;
    EXPECT_NE(text.find("ETA 0.0 s"), std::string::npos) << text;
    // A higher target (a redisplay edit) goes on from there, without a restart.
    const std::uint64_t restarts = viewer->stats().restarts;
    ASSERT_TRUE(viewer->document().set("render.spp", "9"));
    EXPECT_FALSE(viewer->converged());
    traceUntilConverged();
    EXPECT_EQ(spp(), 9u);
    EXPECT_EQ(viewer->stats().restarts, restarts);
}

TEST_F(RenderStopTest, TheTimeBudgetStopsAfterThePassThatCrossesIt) {
    // Even passes (an adaptive render's spp is a mean over the pixels, rounded down, so a render to
    // that mean may stop a pass earlier).
    ASSERT_TRUE(viewer->document().set("render.adaptive", "false"));
    ASSERT_TRUE(viewer->document().set("render.spp", "1000000"));
    ASSERT_TRUE(viewer->document().set("render.time", "0.05"));
    traceUntilConverged();
    const std::uint64_t n = spp();
    EXPECT_GE(viewer->stats().traceSeconds, 0.05);
    EXPECT_GT(n, 0u);
    EXPECT_LT(n, 1000000u);
    expectStopped();
    std::string text = windowText([&] { drawStatsPanel(*viewer, ui); });
    EXPECT_NE(text.find(std::to_string(n) + " spp of 1000000 (done)"), std::string::npos) << text;
    EXPECT_NE(text.find("ETA 0.0 s"), std::string::npos) << text;
    // As raylab-render (src/render/progressive_render.h), the stop comes between passes: every
    // pixel holds the same n samples, so the image is the one of a render of exactly n samples
    // (bit for bit with 1-sample passes). A stop in the middle of a pass would leave the rows
    // already traced with one sample more.
    const Image stopped = viewer->tracer()->readImage();
    ASSERT_TRUE(viewer->document().set("render.time", "0"));
    ASSERT_TRUE(viewer->document().set("render.spp", std::to_string(n)));
    viewer->resetAccumulation();
    traceUntilConverged();
    ASSERT_EQ(spp(), n);
    EXPECT_EQ(viewer->tracer()->readImage().rgba, stopped.rgba);
    // A larger budget (a redisplay edit) goes on from there.
    ASSERT_TRUE(viewer->document().set("render.spp", "1000000"));
    ASSERT_TRUE(viewer->document().set("render.time", "60"));
    EXPECT_FALSE(viewer->converged());
    for (int i = 0; i < 1000 && spp() == n; ++i) viewer->update(0.01);
    EXPECT_GT(spp(), n);
}

} // namespace
} // namespace raylab::ui
