// Classroom mode on a headless viewer: the A/B split screen traces each side exactly as
// raylab-render would with that side's overrides (same seed), the composite takes its columns from
// the right side, equal time keeps the sides' tracing times within the longest pass; bounce
// stepping equals the sum of the bounce views.
#include "app/split_screen.h"
#include "app/ui_state.h"

#include "render/render_helpers.h"
#include "support/debug_view_render.h"
#include "scene/parameters.h"
#include "support/viewer_test_base.h"

#include <gtest/gtest.h>

namespace raylab::ui {
namespace {

class ClassroomTest : public test::ViewerTestBase {
protected:
    void SetUp() override {
        ViewerTestBase::SetUp();
        openSmall("default.json", 48, 27);
        ASSERT_TRUE(viewer->document().set("render.spp", "4"));
    }
    Scene with(const std::vector<std::pair<std::string, std::string>>& overrides) const {
        Scene s = viewer->scene();
        for (const auto& [k, v] : overrides) setParam(s, k, v);
        return s;
    }
    void traceSplit(SplitScreen& split) {
        for (int i = 0; i < 100000 && !split.converged(); ++i) split.update(*viewer, 0.01);
        ASSERT_TRUE(split.converged());
    }
    Image traceViewer() {
        for (int i = 0; i < 100000 && !viewer->converged(); ++i) viewer->update(1e-3);
        return viewer->tracer()->readImage();
    }
};

} // namespace

TEST_F(ClassroomTest, EachHalfOfTheSplitIsThatSidesRender) {
    SplitScreen split;
    EXPECT_EQ(split.addOverride(0, "render.nee", "false", viewer->scene()), "");
    EXPECT_EQ(split.addOverride(1, "render.nee", "true", viewer->scene()), "");
    EXPECT_EQ(split.addOverride(1, "render.max_bounces", "2", viewer->scene()), "");
    EXPECT_NE(split.addOverride(1, "render.bogus", "1", viewer->scene()), "") << "bad keys are refused at once";
    EXPECT_EQ(split.label(1), "B: render.nee=true render.max_bounces=2");
    split.start(SplitBudget::EqualSamples);
    split.divider = 0.25f;
    traceSplit(split);
    EXPECT_EQ(split.accounting().side(0).spp, 4u);
    EXPECT_EQ(split.accounting().side(1).spp, 4u);
    const Image a = test::render(with(split.overrides(0)));   // raylab-render's renderer, same seed
    const Image b = test::render(with(split.overrides(1)));
    EXPECT_EQ(split.image(0).rgba, a.rgba);
    EXPECT_EQ(split.image(1).rgba, b.rgba);
    ASSERT_GT(test::rmse(a, b), 1e-3) << "the two settings must differ for this test to mean anything";
    const Image c = split.composite();
    const int cut = 12;   // 0.25 × 48
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x)
            ASSERT_EQ(c.rgb(x, y), (x < cut ? a : b).rgb(x, y)) << x << " " << y;
    EXPECT_NE(split.displayTexture(0), 0u);
    EXPECT_NE(split.displayTexture(1), 0u);
    // A camera move restarts the viewer: the split follows with both sides.
    ASSERT_TRUE(viewer->document().set("camera.fov", "30"));
    split.update(*viewer, 0.0);
    EXPECT_LE(split.accounting().side(0).spp, 1u);
    split.stop();
    EXPECT_FALSE(split.on());
    EXPECT_TRUE(split.overrides(0).empty());
}

TEST_F(ClassroomTest, ASideTracesADebugViewBesideTheRender) {
    SplitScreen split;
    EXPECT_EQ(split.addOverride(0, "debug-view", "ao", viewer->scene()), "");
    EXPECT_NE(split.addOverride(1, "debug-view", "noise", viewer->scene()), "") << "moments live in the viewer's buffers";
    EXPECT_NE(split.addOverride(1, "debug-view", "boxes", viewer->scene()), "") << "so do the heat maps' scales";
    EXPECT_NE(split.addOverride(1, "debug-view", "bogus", viewer->scene()), "");
    EXPECT_EQ(split.view(1), DebugView::Beauty);
    EXPECT_EQ(split.label(0), "A: debug-view=ao");
    split.start(SplitBudget::EqualSamples);
    traceSplit(split);
    // Side A is raylab-render --debug-view ao of the scene: a grey in [0, 1], below 1 somewhere.
    const Scene s = viewer->scene();
    const Image ao = split.image(0);
    EXPECT_EQ(ao.rgba, test::renderView(s, DebugView::Ao).rgba);
    int occluded = 0;
    for (int y = 0; y < ao.height; ++y)
        for (int x = 0; x < ao.width; ++x) {
            const glm::vec3 c = ao.rgb(x, y);
            ASSERT_TRUE(c.x >= 0.0f && c.x <= 1.0f && c.y == c.x && c.z == c.x) << x << " " << y;
            occluded += c.x < 1.0f;
        }
    EXPECT_GT(occluded, 0);
    // Side B is the render itself.
    EXPECT_EQ(split.image(1).rgba, test::render(s).rgba);
    EXPECT_GT(test::rmse(split.image(0), split.image(1)), 1e-2);
    EXPECT_NE(split.displayTexture(0), 0u);
    // The Debug panel's one click: the baked map beside the traced one.
    split.startViews(DebugView::BakedAo, DebugView::Ao);
    EXPECT_EQ(split.label(0), "A: debug-view=baked-ao");
    EXPECT_EQ(split.label(1), "B: debug-view=ao");
    EXPECT_TRUE(split.on());
    split.stop();
    EXPECT_EQ(split.view(0), DebugView::Beauty);
}

TEST_F(ClassroomTest, EqualTimeKeepsBothSidesWithinTheLongestPass) {
    ASSERT_TRUE(viewer->document().set("render.spp", "24"));
    SplitScreen split;
    split.addOverride(0, "render.max_bounces", "1", viewer->scene());   // cheap
    split.addOverride(1, "render.max_bounces", "8", viewer->scene());   // dearer
    split.start(SplitBudget::EqualTime);
    traceSplit(split);
    const SplitAccounting& acc = split.accounting();
    EXPECT_LE(acc.imbalance(), acc.bound(1));
    EXPECT_GT(acc.side(0).seconds, 0.0);
    EXPECT_GT(acc.side(1).seconds, 0.0);
    EXPECT_TRUE(acc.side(0).spp == 24u || acc.side(1).spp == 24u) << "stops when one side reaches render.spp";
    EXPECT_FALSE(split.series(0).points().empty() && split.series(1).points().empty())
        << "the convergence plot has points: A " << acc.side(0).spp << " spp, B " << acc.side(1).spp << " spp";
}

TEST_F(ClassroomTest, BounceStepKIsTheSumOfBounceViewsZeroToK) {
    for (int k : {1, 3}) {
        SCOPED_TRACE("k = " + std::to_string(k));
        viewer->setDebugView(DebugView::Beauty);
        viewer->setBounceStep(k);
        const Image stepped = traceViewer();
        EXPECT_EQ(viewer->scene().render.maxBounces, 8) << "the scene's own setting is untouched";
        viewer->setBounceStep(0);
        std::vector<double> sum(stepped.rgba.size(), 0.0);
        viewer->setDebugView(DebugView::BounceK);
        for (int j = 0; j <= k; ++j) {
            viewer->setDebugBounce(j);
            viewer->resetAccumulation();
            const Image view = traceViewer();
            for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += view.rgba[i];
        }
        double worst = 0.0;
        for (std::size_t i = 0; i < sum.size(); ++i)
            if (i % 4 != 3) worst = std::max(worst, std::abs(sum[i] - stepped.rgba[i]) / std::max(1e-3, sum[i]));
        EXPECT_LT(worst, 1e-5) << "same seed, same paths: only the order of the sums differs";
    }
    viewer->setDebugView(DebugView::Beauty);
    viewer->setBounceStep(1);
    const Image one = traceViewer();
    viewer->setBounceStep(0);
    EXPECT_GT(test::rmse(one, traceViewer()), 1e-3) << "more bounces, more light";
}

} // namespace raylab::ui
