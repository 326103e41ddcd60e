// The viewer's model on a headless context: parity with the CLI's renderer, triggers, debug views,
// failed loads that keep the previous scene, reload on change.
#include "app/viewer.h"

#include "render/render_helpers.h"
#include "support/viewer_test_base.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace raylab::ui {
namespace {

using test::ViewerTestBase;

class ViewerTest : public ViewerTestBase {
protected:
    void SetUp() override {
        ViewerTestBase::SetUp();
        openSmall("default.json", 48, 27);
    }
    // Traces with a tiny frame budget so passes are cut into bands (and chunks for rpp > 1).
    void traceToTarget() {
        for (int i = 0; i < 100000 && !viewer->converged(); ++i) viewer->update(1e-5);
        ASSERT_TRUE(viewer->converged());
    }
};

TEST_F(ViewerTest, SameImageAsTheHeadlessRendererForOneSamplePasses) {
    ASSERT_TRUE(viewer->document().set("render.spp", "3"));
    traceToTarget();
    const Image shown = viewer->tracer()->readImage();
    const Image reference = test::render(viewer->scene());   // raylab-render's path: whole passes
    ASSERT_EQ(shown.rgba.size(), reference.rgba.size());
    EXPECT_EQ(shown.rgba, reference.rgba);   // bands trace the very samples of whole passes
}

TEST_F(ViewerTest, ChunkedPassesMatchUpToTheRoundingOfTheRunningMean) {
    ASSERT_TRUE(viewer->document().set("render.rpp", "4"));
    ASSERT_TRUE(viewer->document().set("render.spp", "8"));
    traceToTarget();
    EXPECT_EQ(viewer->tracer()->passes(), 2u);
    const Image shown = viewer->tracer()->readImage();
    const Image reference = test::render(viewer->scene());
    // Same samples; only the order of the running-mean updates differs (float32: a few ulps).
    double worst = 0.0;
    for (std::size_t i = 0; i < shown.rgba.size(); ++i)
        worst = std::max(worst, std::abs(double(shown.rgba[i]) - reference.rgba[i]) / std::max(1e-3, double(std::abs(reference.rgba[i]))));
    EXPECT_LT(worst, 1e-5);
}

TEST_F(ViewerTest, EditsDoWhatTheirTriggerSays) {
    ASSERT_TRUE(viewer->document().set("render.spp", "2"));
    traceToTarget();
    ASSERT_EQ(viewer->tracer()->samplesPerPixel(), 2u);
    ASSERT_TRUE(viewer->document().set("render.exposure", "1"));   // redisplay: the samples stay
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 2u);
    ASSERT_TRUE(viewer->document().set("camera.fov", "50"));       // reset accumulation
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 0u);
    EXPECT_FALSE(viewer->document().set("camera.fov", "500"));     // refused: nothing changes
    EXPECT_FLOAT_EQ(viewer->scene().camera.fovY, 50.0f);
    EXPECT_NE(viewer->document().lastError().find("camera.fov"), std::string::npos);
    viewer->setResolutionScale(0.5f);
    EXPECT_EQ(viewer->tracer()->width(), 24);
    EXPECT_EQ(viewer->tracer()->height(), 14);
}

TEST_F(ViewerTest, DebugViewsShowNormalsNotRadiance) {
    ASSERT_TRUE(viewer->document().set("render.spp", "2"));
    traceToTarget();
    const Image beauty = viewer->tracer()->readImage();
    viewer->setDebugView(DebugView::Normals);
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 0u);   // another quantity: restarted
    traceToTarget();
    const Image normals = viewer->tracer()->readImage();
    EXPECT_GT(test::rmse(beauty, normals), 0.05);
    // The bottom-centre pixel sees the flat-ish ground: normal (0, 1, 0) shown as (0.5, 1, 0.5).
    const glm::vec3 ground = normals.rgb(24, 26);
    EXPECT_NEAR(ground.x, 0.5f, 0.02f);
    EXPECT_NEAR(ground.y, 1.0f, 0.02f);
    EXPECT_NEAR(ground.z, 0.5f, 0.02f);
    for (std::size_t i = 0; i < normals.rgba.size(); ++i) {
        EXPECT_GE(normals.rgba[i], 0.0f);
        EXPECT_LE(normals.rgba[i], 1.0f);
    }
    // Noise and NaN views are drawn from the beauty path's moments: switching between them keeps
    // the samples, and the traced beauty image is the plain one.
    viewer->setDebugView(DebugView::Noise);
    traceToTarget();
    viewer->setDebugView(DebugView::NonFinite);
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 2u);
    EXPECT_NE(viewer->displayTexture(), 0u);
    EXPECT_EQ(viewer->tracer()->readImage().rgba, beauty.rgba);
}

// The samples view draws the count of each pixel over the beauty render, which goes on untouched:
// adaptive sampling's blocks of different counts in different colours, its largest count red;
// even spreading one colour.
TEST_F(ViewerTest, TheSamplesViewShowsEachPixelsSamplesOverTheRenderItKeeps) {
    openSmall("cornell_box.json", 32, 18);
    ASSERT_TRUE(viewer->document().set("render.rpp", "8"));
    ASSERT_TRUE(viewer->document().set("render.spp", "48"));
    traceToTarget();
    ASSERT_TRUE(viewer->tracer()->adaptive());
    const Image beauty = viewer->tracer()->readImage();
    const std::vector<std::uint64_t> samples = viewer->tracer()->pixelSamples();
    viewer->setDebugView(DebugView::Samples);
    EXPECT_EQ(viewer->tracer()->pixelSamples(), samples) << "the view keeps the render";
    const auto shown = [&] {
        const unsigned texture = viewer->displayTexture();
        std::vector<std::uint8_t> rgba(32 * 18 * 4);
        glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
        return rgba;
    };
    std::vector<std::uint8_t> rgba = shown();
    const std::uint64_t most = *std::max_element(samples.begin(), samples.end());
    EXPECT_FLOAT_EQ(viewer->heatScaleInUse(), float(most));
    int pairs = 0;
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 32; ++x) {
            // GL's rows are bottom first, pixelSamples' top first.
            const std::size_t i = std::size_t(y) * 32 + std::size_t(x), j = std::size_t(17 - y) * 32 + std::size_t(x);
            const std::size_t k = std::size_t(17) * 32 + 31;   // the top-right pixel, as a second one
            const bool sameCount = samples[i] == samples[k];
            const bool sameColour = std::equal(&rgba[4 * j], &rgba[4 * j + 3], &rgba[4 * 31]);
            EXPECT_EQ(sameCount, sameColour) << "pixel (" << x << ", " << y << ")";
            pairs += !sameCount;
        }
    EXPECT_GT(pairs, 0) << "the blocks should hold different counts";
    viewer->setDebugView(DebugView::Beauty);
    EXPECT_EQ(viewer->tracer()->readImage().rgba, beauty.rgba);

    ASSERT_TRUE(viewer->document().set("render.adaptive", "false"));
    traceToTarget();
    viewer->setDebugView(DebugView::Samples);
    rgba = shown();
    for (std::size_t i = 1; i < 32 * 18; ++i)
        ASSERT_TRUE(std::equal(&rgba[4 * i], &rgba[4 * i + 3], &rgba[0])) << "even spreading: one colour";
    EXPECT_FLOAT_EQ(viewer->heatScaleInUse(), 48.0f);
}

TEST_F(ViewerTest, DirectPlusIndirectIsTheBeautyImageAndBouncesSplitIt) {
    // The bounce views only filter what the integrator adds; the paths (same seed) are the same.
    ASSERT_TRUE(viewer->document().set("render.spp", "2"));
    traceToTarget();
    const Image beauty = viewer->tracer()->readImage();
    auto trace = [&](DebugView v, int k = 1) {
        viewer->setDebugBounce(k);
        viewer->setDebugView(v);
        traceToTarget();
        return viewer->tracer()->readImage();
    };
    const Image direct = trace(DebugView::Direct);
    const Image indirect = trace(DebugView::Indirect);
    const Image k0 = trace(DebugView::BounceK, 0);
    const Image k1 = trace(DebugView::BounceK, 1);
    double worst = 0.0, indirectSum = 0.0;
    for (std::size_t i = 0; i < beauty.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        // Float rounding only: the same terms summed in another order.
        const double scale = std::max(1e-3, double(beauty.rgba[i]));
        worst = std::max(worst, std::abs(double(direct.rgba[i]) + indirect.rgba[i] - beauty.rgba[i]) / scale);
        worst = std::max(worst, std::abs(double(k0.rgba[i]) + k1.rgba[i] - direct.rgba[i]) / scale);
        indirectSum += indirect.rgba[i];
    }
    EXPECT_LT(worst, 1e-5);
    EXPECT_GT(indirectSum, 1.0);   // the ground lights the spheres: indirect light is not nothing
    // The sky seen straight on is bounce 0 only.
    EXPECT_EQ(k1.rgb(24, 0), glm::vec3(0.0f));
    EXPECT_GT(k0.rgb(24, 0).z, 0.5f);
}

TEST_F(ViewerTest, ABrokenSceneFileKeepsThePreviousSceneAndImage) {
    ASSERT_TRUE(viewer->document().set("render.spp", "2"));
    traceToTarget();
    const Image before = viewer->tracer()->readImage();
    const auto broken = std::filesystem::temp_directory_path() / "raylab_viewer_broken.json";
    std::ofstream(broken) << "{\n  \"camera\": { \"fov\": -3 }\n}\n";
    EXPECT_FALSE(viewer->openScene(broken));
    EXPECT_NE(viewer->document().lastError().find("raylab_viewer_broken.json:2:"), std::string::npos) << viewer->document().lastError();
    EXPECT_EQ(viewer->scene().render.width, 48);
    EXPECT_EQ(viewer->tracer()->readImage().rgba, before.rgba);
    ASSERT_FALSE(log.entries().empty());
    EXPECT_EQ(log.entries().front().level, LogEntry::Level::Error);
    std::filesystem::remove(broken);
}

TEST_F(ViewerTest, ReloadsTheSceneWhenTheFileChanges) {
    const auto file = std::filesystem::temp_directory_path() / "raylab_viewer_reload.json";
    std::ofstream(file) << R"({"render": {"width": 16, "height": 8}, "camera": {"fov": 30}, "objects": [{"type": "sphere"}]})";
    ASSERT_TRUE(viewer->openScene(file)) << viewer->document().lastError();
    EXPECT_FLOAT_EQ(viewer->scene().camera.fovY, 30.0f);
    std::ofstream(file) << R"({"render": {"width": 16, "height": 8}, "camera": {"fov": 45.5}, "objects": [{"type": "sphere"}]})";
    viewer->pollFileChanges();
    EXPECT_FLOAT_EQ(viewer->scene().camera.fovY, 45.5f);
    std::ofstream(file) << R"({"render": {"width": 16, "height": 8}, "camera": {"fov": "wide"}, "objects": [{"type": "sphere"}]})";
    viewer->pollFileChanges();   // broken on disk: the running scene stays
    EXPECT_FLOAT_EQ(viewer->scene().camera.fovY, 45.5f);
    EXPECT_NE(viewer->document().lastError().find("raylab_viewer_reload.json:1:"), std::string::npos) << viewer->document().lastError();
    std::filesystem::remove(file);
}

TEST_F(ViewerTest, SavedScenesLoadBackTheSame) {
    ASSERT_TRUE(viewer->document().set("materials.red.albedo", "[0.1, 0.2, 0.3]"));
    const auto file = std::filesystem::temp_directory_path() / "raylab_viewer_saved.json";
    ASSERT_TRUE(viewer->document().save(file));
    const Scene back = loadScene(file);
    EXPECT_EQ(sceneToJson(back), sceneToJson(viewer->scene()));
    std::filesystem::remove(file);
}

TEST_F(ViewerTest, AShaderThatFailsToCompileKeepsThePreviousOneRunning) {
    ASSERT_TRUE(viewer->document().set("render.spp", "1"));
    traceToTarget();
    const Image before = viewer->tracer()->readImage();
    // A copy of the shaders with an error on line 3 of the debug-view include.
    const auto dir = std::filesystem::temp_directory_path() / "raylab_viewer_bad_shaders";
    std::filesystem::remove_all(dir);
    std::filesystem::copy(std::string(RAYLAB_SOURCE_DIR) + "/shaders", dir, std::filesystem::copy_options::recursive);
    {
        std::ifstream in(dir / "include" / "debug_views.glsl");
        std::stringstream text;
        text << in.rdbuf();
        std::string src = text.str();
        const auto third = src.find('\n', src.find('\n') + 1) + 1;
        src.insert(third, "this is not glsl;\n");
        std::ofstream(dir / "include" / "debug_views.glsl") << src;
    }
    ::setenv("RAYLAB_SHADER_DIR", dir.c_str(), 1);
    viewer->setDebugView(DebugView::Normals);   // needs the debug-view variant: compiled now
    ::unsetenv("RAYLAB_SHADER_DIR");
    EXPECT_EQ(viewer->debugView(), DebugView::Beauty);
    EXPECT_NE(viewer->document().lastError().find("debug_views.glsl:3"), std::string::npos) << viewer->document().lastError();
    EXPECT_EQ(viewer->tracer()->readImage().rgba, before.rgba);
    ASSERT_TRUE(viewer->document().set("render.spp", "2"));   // the previous program still traces
    traceToTarget();
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 2u);
    std::filesystem::remove_all(dir);
}

TEST_F(ViewerTest, PickingSelectsTheObjectUnderThePixel) {
    EXPECT_EQ(viewer->pick(24.0f, 26.0f), 0);   // the ground
    EXPECT_EQ(viewer->selection.object(), 0);
    EXPECT_FALSE(viewer->pick(24.0f, 0.5f));    // sky
    EXPECT_EQ(viewer->selection.object(), -1);
}

} // namespace
} // namespace raylab::ui
