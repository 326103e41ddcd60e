#include "app/pass_slicer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include <functional>
#include <vector>

namespace raylab::ui {
namespace {

// Replays units until `passes` passes end, with a simulated cost per pixel-sample of each row, and
// checks that every row received exactly the pass's samples, in order, before the pass ended.
// Reports the largest unit after the first two, the probes (in pixel-samples and in seconds).
struct Largest {
    int work = 0;
    double seconds = 0.0;
    double secondsAfterFirstPass = 0.0;
};
void checkPasses(int width, int height, int rpp, const std::function<double(int)>& costOfRow, double budget, int passes,
                 Largest* largest = nullptr) {
    PassSlicer slicer;
    slicer.restart(width, height, rpp);
    std::vector<int> rowSamples(std::size_t(height), 0);
    int ended = 0;
    Largest max;
    for (int guard = 0; ended < passes && guard < 1000000; ++guard) {
        const WorkUnit u = slicer.next(budget);
        ASSERT_GE(u.rows, 1);
        ASSERT_LE(u.y + u.rows, height);
        ASSERT_GE(u.rpp, 1);
        double seconds = 0.0;
        for (int y = u.y; y < u.y + u.rows; ++y) {
            ASSERT_EQ(rowSamples[std::size_t(y)], u.sampleOffset) << "row " << y << " out of order";
            rowSamples[std::size_t(y)] += u.rpp;
            seconds += costOfRow(y) * width * u.rpp;
        }
        if (guard > 1) {   // after the two probes (the first unit is a program's first draw: not measured)
            max.work = std::max(max.work, width * u.rows * u.rpp);
            max.seconds = std::max(max.seconds, seconds);
            if (ended > 0) max.secondsAfterFirstPass = std::max(max.secondsAfterFirstPass, seconds);
        }
        slicer.measured(u, seconds);
        if (u.endsPass) {
            ASSERT_EQ(u.passRpp, rpp);
            for (int s : rowSamples) ASSERT_EQ(s, rpp);
            std::fill(rowSamples.begin(), rowSamples.end(), 0);
            ++ended;
        }
    }
    EXPECT_EQ(ended, passes);
    if (largest) *largest = max;
}

void checkPasses(int width, int height, int rpp, double cost, double budget, int passes, int* maxWorkOut = nullptr) {
    Largest largest;
    checkPasses(width, height, rpp, [cost](int) { return cost; }, budget, passes, &largest);
    if (maxWorkOut) *maxWorkOut = largest.work;
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

TEST(PassSlicer, UnitsFollowTheCostOfTheRowsTheyCover) {
    // The default scene's image: the sky in the top rows (GL rows 252-359) costs a twentieth of
    // the ground below (a miss against a path of bounces). A unit sized by the cost of the rows
    // just traced (the cheap sky, at the end of each chunk) and spent on the ground (the next
    // chunk's first rows) would take up to 20 times its budget; sized by its own rows' costs, it
    // stays near the budget once each row has been measured (in the first pass of 64 samples).
    const auto sky = [](int y) { return y >= 252 ? 5e-8 : 1e-6; };
    for (bool upsideDown : {false, true}) {
        SCOPED_TRACE(upsideDown ? "the costly rows last" : "the costly rows first");
        Largest largest;
        checkPasses(640, 360, 64, [&](int y) { return sky(upsideDown ? 359 - y : y); }, 0.01, 2, &largest);
        std::printf("largest unit: %.2f ms, after the first pass %.2f ms, for a 10 ms budget\n", largest.seconds * 1e3,
                    largest.secondsAfterFirstPass * 1e3);
        EXPECT_LE(largest.secondsAfterFirstPass, 0.0105);
        // In the first pass, rows not measured yet may cost what the first unit (1/8 of the
        // image, one sample) did: 640 x 45 x 1 µs.
        EXPECT_LE(largest.seconds, 640 * 45 * 1e-6 + 1e-9);
    }
}

// Traces with `cost` per pixel-sample until `units` units are done; returns the longest.
double longestUnit(PassSlicer& slicer, int width, const std::function<double(int)>& cost, double budget, int units) {
    double longest = 0.0;
    for (int i = 0; i < units; ++i) {
        const WorkUnit u = slicer.next(budget);
        double seconds = 0.0;
        for (int y = u.y; y < u.y + u.rows; ++y) seconds += cost(y) * width * u.rpp;
        slicer.measured(u, seconds);
        longest = std::max(longest, seconds);
    }
    return longest;
}

TEST(PassSlicer, AfterForgettingCostsUnitsStartSmall) {
    // Learnt on a cheap view (normals: one ray), then a path-traced view 50 times dearer.
    PassSlicer slicer;
    slicer.restart(640, 360, 64);
    longestUnit(slicer, 640, [](int) { return 2e-8; }, 0.01, 400);
    slicer.forgetCosts();
    slicer.restart(640, 360, 64);
    const WorkUnit first = slicer.next(0.01);
    EXPECT_EQ(first.rows, 45);   // as for the first image: 1/8 of the rows, one sample
    EXPECT_EQ(first.rpp, 1);
    // The new program's first draw includes its JIT compile: not a cost to size units by.
    slicer.measured(first, 0.2);
    const WorkUnit second = slicer.next(0.01);
    EXPECT_EQ(second.rows, 45);
    EXPECT_EQ(second.rpp, 1);
    slicer.measured(second, 1e-6 * 640 * 45);
    // Rows not measured since count as dear as the dearest measured: no unit overshoots.
    EXPECT_LE(longestUnit(slicer, 640, [](int) { return 1e-6; }, 0.01, 200), 0.0101);
}

TEST(PassSlicer, AFarSlowerUnitMakesEveryRowDearer) {
    // Without forgetting (an edit: more bounces, the camera turned to the ground): the first unit
    // after the change overshoots by the ratio; the ones after it, on rows not traced since the
    // change, do not.
    PassSlicer slicer;
    slicer.restart(640, 360, 64);
    longestUnit(slicer, 640, [](int) { return 5e-8; }, 0.01, 400);
    slicer.restart(640, 360, 64);
    const double first = longestUnit(slicer, 640, [](int) { return 1e-6; }, 0.01, 1);
    EXPECT_GT(first, 0.1);   // 20 times the budget: what one unit cannot know
    EXPECT_LE(longestUnit(slicer, 640, [](int) { return 1e-6; }, 0.01, 200), 0.0101);
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
