#include "app/frame_pacer.h"

#include <gtest/gtest.h>

namespace raylab::ui {
namespace {

TEST(FramePacer, TracingGetsWhatTheRestOfTheFrameLeaves) {
    FramePacer p(0.030, 0.002);
    EXPECT_DOUBLE_EQ(p.traceBudget(), 0.030);   // nothing measured yet
    p.frameDone(0.040, 0.030);                  // 10 ms of UI
    EXPECT_NEAR(p.traceBudget(), 0.020, 1e-12);
    for (int i = 0; i < 50; ++i) p.frameDone(0.025, 0.010);   // the UI now costs 15 ms
    EXPECT_NEAR(p.traceBudget(), 0.015, 1e-4);
    for (int i = 0; i < 50; ++i) p.frameDone(0.028, 0.002);   // 26 ms: what is left (4 ms) is less than a third
    EXPECT_NEAR(p.traceBudget(), 0.026 / 3.0, 1e-4);
}

TEST(FramePacer, OverTheTargetTracingKeepsAShareOfTheFrame) {
    FramePacer p(0.030, 0.002);
    for (int i = 0; i < 80; ++i) p.frameDone(0.100, 0.010);   // a loaded machine: the UI costs 90 ms
    EXPECT_NEAR(p.otherSeconds(), 0.090, 1e-4);
    EXPECT_NEAR(p.traceBudget(), 0.030, 1e-4);   // a third of 90 ms, capped at the target
    for (int i = 0; i < 80; ++i) p.frameDone(0.045, 0.010);   // 35 ms of UI: 11.7 ms of tracing
    EXPECT_NEAR(p.traceBudget(), 0.035 / 3.0, 1e-4);
    FramePacer tiny(0.030, 0.002);
    for (int i = 0; i < 80; ++i) tiny.frameDone(0.0305, 0.0005);   // 30 ms of UI: 10 ms, not the 2 ms floor
    EXPECT_NEAR(tiny.traceBudget(), 0.010, 1e-4);
}

} // namespace
} // namespace raylab::ui
