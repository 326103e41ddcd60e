#include "app/frame_pacer.h"

#include <gtest/gtest.h>

namespace raylab::ui {
namespace {

TEST(FramePacer, TracingGetsWhatTheRestOfTheFrameLeaves) {
    FramePacer p(0.030, 0.002);
    EXPECT_DOUBLE_EQ(p.traceBudget(), 0.030);   // nothing measured yet
    p.frameDone(0.040, 0.030);                  // 10 ms of UI
    EXPECT_NEAR(p.traceBudget(), 0.020, 1e-12);
    for (int i = 0; i < 50; ++i) p.frameDone(0.050, 0.010);   // the UI now costs 40 ms
    EXPECT_NEAR(p.otherSeconds(), 0.040, 1e-4);
    EXPECT_DOUBLE_EQ(p.traceBudget(), 0.002);   // never starved completely
}

} // namespace
} // namespace raylab::ui
