// The viewer's path inspector model on a headless context: the recorded paths are the very
// samples the viewer traces next (under the beauty view and the bounce views), they follow bounce
// stepping, clicks in inspect mode inspect, following records again after a restart, and the
// overlay lines come from the recorded hits.
#include "app/inspection.h"
#include "app/viewer.h"
#include "app/viewport_click.h"

#include "inspect/path_checks.h"
#include "render/render_helpers.h"
#include "support/viewer_test_base.h"

#include <gtest/gtest.h>

namespace raylab::ui {
namespace {

class InspectionTest : public test::ViewerTestBase {
protected:
    void SetUp() override {
        ViewerTestBase::SetUp();
        openSmall("default.json", 48, 27);
    }
    // The Cornell box (meshes, a triangle lamp): every path bounces on, with light at each bounce.
    void openCornellBox() {
        openSmall("cornell_box.json", 48, 27);
        ASSERT_TRUE(viewer->document().set("render.nee", "true"));
    }
    void traceToTarget() {
        for (int i = 0; i < 100000 && !viewer->converged(); ++i) viewer->update(1e-5);
        ASSERT_TRUE(viewer->converged());
    }
    // The paths recorded at pixel (x, y) after `done` samples (mean `before`) are the samples it
    // takes next: traced on, its mean takes exactly their values.
    void expectPixelTakesTheValues(int x, int y, glm::vec4 before, int done, const std::vector<PathRecord>& paths,
                                   const std::string& where) {
        const int spp = done + int(paths.size());
        ASSERT_TRUE(viewer->document().set("render.spp", std::to_string(spp)));   // no restart: spp is a stop condition
        traceToTarget();
        glm::vec3 sum(0.0f);
        for (const PathRecord& p : paths) sum += p.value;
        const glm::vec3 expected = (glm::vec3(before) * float(done) + sum) / float(spp);
        const glm::vec4 after = viewer->pixelValue(x, y);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[c], expected[c], 1e-5f * (1.0f + expected[c])) << where << " " << c;
    }
};

TEST_F(InspectionTest, RecordedPathsAreTheSamplesTheViewerTracesNext) {
    ASSERT_TRUE(viewer->document().set("render.rpp", "4"));
    ASSERT_TRUE(viewer->document().set("render.spp", "4"));
    traceToTarget();
    const int x = 24, y = 14;
    const glm::vec4 before = viewer->pixelValue(x, y);
    viewer->inspection.pathCount = 4;
    ASSERT_TRUE(viewer->inspection.inspect(*viewer, x, y));
    const auto paths = viewer->inspection.paths();
    ASSERT_EQ(paths.size(), 4u);
    EXPECT_EQ(paths[0].sample, 4u);   // the next sample of the pixel's sequence
    expectPixelTakesTheValues(x, y, before, 4, paths, "beauty");
}

// Under the bounce views (bounce k, direct, indirect) the inspector records through the same
// bounce filter: the recorded values are the samples the view adds to the pixel next, and the
// terms of the bounces the view leaves out are marked and not summed.
TEST_F(InspectionTest, UnderTheBounceViewsTheValuesAreThePixelsOwn) {
    openCornellBox();
    ASSERT_TRUE(viewer->document().set("render.rpp", "4"));
    const int x = 24, y = 6;   // the back wall: it sees the lamp
    struct Case {
        DebugView view;
        int bounce;
        BounceFilter filter;
    };
    int notCounted = 0;
    for (const Case& c : {Case{DebugView::BounceK, 1, BounceFilter::Only}, Case{DebugView::BounceK, 2, BounceFilter::Only},
                          Case{DebugView::Direct, 1, BounceFilter::Direct}, Case{DebugView::Indirect, 1, BounceFilter::Indirect}}) {
        const std::string where = std::string(debugViewName(c.view)) + " " + std::to_string(c.bounce);
        ASSERT_TRUE(viewer->document().set("render.spp", "4"));
        viewer->setDebugView(c.view);
        viewer->setDebugBounce(c.bounce);
        viewer->resetAccumulation();
        traceToTarget();
        const glm::vec4 before = viewer->pixelValue(x, y);
        viewer->inspection.pathCount = 16;
        ASSERT_TRUE(viewer->inspection.inspect(*viewer, x, y)) << where;
        EXPECT_EQ(viewer->inspection.filter(), c.filter) << where;
        const auto paths = viewer->inspection.paths();
        notCounted += test::expectTermsMultiplyOut(paths, where).notCounted;
        expectPixelTakesTheValues(x, y, before, 4, paths, where);
    }
    EXPECT_GT(notCounted, 10) << "the views left terms out";
    // Views that trace no light paths record the beauty estimator.
    viewer->setDebugView(DebugView::Normals);
    ASSERT_TRUE(viewer->inspection.inspect(*viewer, x, y));
    EXPECT_EQ(viewer->inspection.filter(), BounceFilter::All);
    for (const PathRecord& p : viewer->inspection.paths())
        for (const BounceRecord& b : p.bounces) EXPECT_TRUE(b.emissionCounted && b.lightCounted);
}

// Bounce stepping caps the bounces the tracer follows; the inspected paths follow it: at most
// k + 1 bounce records (the camera ray's hit and k scattered rays), the last one unsampled, and
// the recorded terms still multiply out to values the pixel gets.
TEST_F(InspectionTest, InspectionFollowsBounceStepping) {
    openCornellBox();
    const int x = 24, y = 6;   // the back wall: it sees the lamp
    viewer->inspection.pathCount = 32;
    ASSERT_TRUE(viewer->inspection.inspect(*viewer, x, y));
    std::size_t longest = 0;
    for (const PathRecord& p : viewer->inspection.paths()) longest = std::max(longest, p.bounces.size());
    EXPECT_GT(longest, 3u) << "without stepping some paths are longer than the step below allows";
    for (int k : {1, 2}) {
        viewer->setBounceStep(k);
        ASSERT_TRUE(viewer->inspection.inspect(*viewer, x, y));
        const auto& paths = viewer->inspection.paths();
        test::expectTermsMultiplyOut(paths, "bounce step " + std::to_string(k));
        std::size_t reachedCap = 0;
        for (const PathRecord& p : paths) {
            ASSERT_LE(p.bounces.size(), std::size_t(k + 1)) << "bounce step " << k;
            if (p.bounces.size() == std::size_t(k + 1) && p.bounces.back().hit) {
                ++reachedCap;
                EXPECT_FALSE(p.bounces.back().sampled) << "bounce step " << k << ": the last bounce scatters no further";
                EXPECT_EQ(p.bounces.back().lightStatus, LightStatus::None) << "nor samples a light";
            }
        }
        EXPECT_GT(reachedCap, 0u) << "bounce step " << k;
    }
    // The recorded values are what the stepped image gets.
    ASSERT_TRUE(viewer->document().set("render.rpp", "4"));
    ASSERT_TRUE(viewer->document().set("render.spp", "4"));
    viewer->resetAccumulation();
    traceToTarget();
    const glm::vec4 before = viewer->pixelValue(x, y);
    viewer->inspection.pathCount = 4;
    ASSERT_TRUE(viewer->inspection.inspect(*viewer, x, y));
    expectPixelTakesTheValues(x, y, before, 4, viewer->inspection.paths(), "bounce step 2");
}

TEST_F(InspectionTest, ClicksInInspectModeInspectAndFollowingRecordsAgain) {
    UiState ui;
    ui.image = ImageRect{100, 50, 96, 54};   // the 48 × 27 image shown at twice its size
    viewer->inspection.clickInspects = true;
    viewportClick(*viewer, ui, 100 + 2 * 10.5f, 50 + 2 * 20.5f);
    ASSERT_TRUE(viewer->inspection.active());
    EXPECT_EQ(viewer->inspection.x(), 10);
    EXPECT_EQ(viewer->inspection.y(), 20);
    EXPECT_EQ(viewer->selection.object(), -1) << "inspect mode does not pick";
    const auto first = viewer->inspection.paths();
    // A camera move restarts the image; following records again once the restarts settle.
    viewer->scene().camera.position.x += 0.5f;
    viewer->document().changed(Trigger::ResetAccumulation);
    viewer->inspection.update(*viewer);
    viewer->inspection.update(*viewer);
    ASSERT_EQ(viewer->inspection.paths().size(), first.size());
    EXPECT_NE(viewer->inspection.paths()[0].bounces[0].origin, first[0].bounces[0].origin);
    // Outside the image: an error, the previous paths stay.
    EXPECT_FALSE(viewer->inspection.inspect(*viewer, 48, 0));
    EXPECT_TRUE(viewer->inspection.active());
}

TEST_F(InspectionTest, OverlayHasASegmentAndADotPerSurfaceHit) {
    viewer->inspection.pathCount = 6;
    ASSERT_TRUE(viewer->inspection.inspect(*viewer, 24, 20));   // the ground, in front
    PathOverlaySettings only;
    only.normals = only.sampled = only.shadowRays = false;
    const Scene traced = viewer->tracedScene();
    const PathOverlay o = pathOverlay(traced, 48, 27, viewer->inspection.paths(), only);
    std::size_t hits = 0, misses = 0;
    for (const PathRecord& p : viewer->inspection.paths())
        for (const BounceRecord& b : p.bounces) (b.hit ? hits : misses) += 1;
    ASSERT_GT(hits, 0u);
    EXPECT_EQ(o.hits.size(), hits);   // every hit is in front of the camera here
    EXPECT_LE(o.lines.size(), hits + misses);
    // The first hit of every path projects into the inspected pixel.
    for (const PathDot& d : o.hits) {
        if (d.bounce != 0) continue;
        EXPECT_NEAR(d.point.x, 24.5f, 0.5f);
        EXPECT_NEAR(d.point.y, 20.5f, 0.5f);
    }
    // One path only.
    EXPECT_LT(pathOverlay(traced, 48, 27, viewer->inspection.paths(), only, 0).hits.size(), hits);
}

} // namespace
} // namespace raylab::ui
