#include "app/pass_slicer.h"

#include <gtest/gtest.h>

#include <vector>

namespace raylab::ui {
namespace {

// Replays units until `passes` passes end, with a simulated cost per pixel-sample, and checks that
// every row received exactly the pass's samples, in order, before the pass ended.
void checkPasses(int width, int height, int rpp, double cost, double budget, int passes, int* maxWorkOut = nullptr) {
    PassSlicer slicer;
    slicer.restart(width, height, rpp);
    std::vector<int> rowSamples(std::size_t(height), 0);
    int ended = 0;
    int maxWork = 0;
    for (int guard = 0; ended < passes && guard < 1000000; ++guard) {
        const WorkUnit u = slicer.next(budget);
        ASSERT_GE(u.rows, 1);
        ASSERT_LE(u.y + u.rows, height);
        ASSERT_GE(u.rpp, 1);
        for (int y = u.y; y < u.y + u.rows; ++y) {
            ASSERT_EQ(rowSamples[std::size_t(y)], u.sampleOffset) << "row " << y << " out of order";
            rowSamples[std::size_t(y)] += u.rpp;
        }
        if (guard > 0) maxWork = std::max(maxWork, width * u.rows * u.rpp);   // after the first measurement
        slicer.measured(u, cost * width * u.rows * u.rpp);
        if (u.endsPass) {
            ASSERT_EQ(u.passRpp, rpp);
            for (int s : rowSamples) ASSERT_EQ(s, rpp);
            std::fill(rowSamples.begin(), rowSamples.end(), 0);
            ++ended;
        }
    }
    EXPECT_EQ(ended, passes);
    if (maxWorkOut) *maxWorkOut = maxWork;
}

TEST(PassSlicer, EveryRowGetsEveryPassSampleExactlyOnce) {
    checkPasses(64, 37, 1, 1e-6, 0.001, 5);
    checkPasses(64, 37, 7, 1e-6, 0.001, 3);
    checkPasses(64, 37, 16, 1e-9, 0.001, 3);   // cheap: whole chunks of the image per unit
}

TEST(PassSlicer, UnitsStayWithinTheBudgetHoweverLargeTheRpp) {
    // 640 x 360 at 1 µs per pixel-sample: a 1024-rpp pass is 236 s of work; a 20 ms budget allows
    // 20000 pixel-samples, i.e. 31 rows of one sample.
    int maxWork = 0;
    checkPasses(640, 360, 1024, 1e-6, 0.02, 1, &maxWork);
    EXPECT_LE(maxWork, 20000);
    EXPECT_GE(maxWork, 20000 - 640);
}

TEST(PassSlicer, AFullImageChunkWhenItFits) {
    PassSlicer slicer;
    slicer.restart(100, 100, 64);
    // 1e-7 s per pixel-sample: 10^7 fit in 1 s, so once measured, the next chunk is the rest of
    // the pass over the whole image.
    WorkUnit u;
    do {
        u = slicer.next(1.0);
        slicer.measured(u, 1e-7 * 100 * u.rows * u.rpp);
    } while (u.y + u.rows < 100);
    u = slicer.next(1.0);
    EXPECT_EQ(u.y, 0);
    EXPECT_EQ(u.rows, 100);
    EXPECT_EQ(u.sampleOffset, 1);
    EXPECT_EQ(u.rpp, 63);
    EXPECT_TRUE(u.endsPass);
}

} // namespace
} // namespace raylab::ui
