// The panels in ImGui frames without a window (as imgui's example_null does): font atlas built,
// display size set, NewFrame/Render; the viewer runs on the headless context.
#include "panels/panels.h"

#include "render/render_helpers.h"
#include "support/gl_test.h"
#include "support/panel_frame_test.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

namespace raylab::ui {
namespace {

class PanelsTest : public test::PanelFrameTest {};

TEST_F(PanelsTest, TheWorkspaceDrawsEveryPanelAndLaysTheImageOut) {
    viewer->selection.select(2);
    for (int i = 0; i < 3; ++i) frame();
    for (const char* name : {"Viewport", "Render", "Camera", "Material", "Overlays", "Debug views", "Stats", "Log"})
        EXPECT_NE(ImGui::FindWindowByName(name), nullptr) << name;
    ASSERT_TRUE(ui.image.valid());
    // The image keeps the traced aspect ratio inside the viewport.
    EXPECT_NEAR(ui.image.width / ui.image.height, 32.0f / 18.0f, 0.01f);
    const ImGuiWindow* vp = ImGui::FindWindowByName("Viewport");
    EXPECT_GE(ui.image.x, vp->Pos.x);
    EXPECT_LE(ui.image.x + ui.image.width, vp->Pos.x + vp->Size.x + 0.5f);
}

TEST_F(PanelsTest, DrawingChangesNothingAndAClickOnTheImagePicks) {
    const nlohmann::json before = sceneToJson(viewer->scene());
    for (int i = 0; i < 3; ++i) frame();
    EXPECT_EQ(sceneToJson(viewer->scene()), before);
    // The bottom-centre of the image shows the ground (object 0); above the image is no pick.
    viewportClick(*viewer, ui, ui.image.x + ui.image.width * 0.5f, ui.image.y + ui.image.height - 1.0f);
    EXPECT_EQ(viewer->selection.object(), 0);
    viewportClick(*viewer, ui, ui.image.x + 1.0f, ui.image.y - 5.0f);
    EXPECT_EQ(viewer->selection.object(), 0);   // outside: unchanged
}

TEST_F(PanelsTest, ClickToFocusModeFocusesInsteadOfPickingOnce) {
    for (int i = 0; i < 2; ++i) frame();
    viewer->selection.select(3);
    ui.focusOnClick = true;
    const float before = viewer->scene().camera.focusDistance;
    viewportClick(*viewer, ui, ui.image.x + ui.image.width * 0.5f, ui.image.y + ui.image.height - 1.0f);
    EXPECT_FALSE(ui.focusOnClick) << "the mode ends with the click";
    EXPECT_EQ(viewer->selection.object(), 3) << "a focusing click does not pick";
    EXPECT_NE(viewer->scene().camera.focusDistance, before);
    EXPECT_GT(viewer->scene().camera.focusDistance, 0.0f);
    viewportClick(*viewer, ui, ui.image.x + ui.image.width * 0.5f, ui.image.y + ui.image.height - 1.0f);
    EXPECT_EQ(viewer->selection.object(), 0) << "the next click picks again";
}

TEST_F(PanelsTest, HeatMapsAndBvhOverlaysDraw) {
    viewer->overlays.bvh = true;
    viewer->overlays.meshBvh = true;
    viewer->overlays.bvhDepth = 2;
    for (DebugView v : {DebugView::Boxes, DebugView::Triangles, DebugView::Uv}) {
        viewer->setDebugView(v);
        EXPECT_EQ(viewer->debugView(), v) << viewer->document().lastError();
        for (int i = 0; i < 2; ++i) {
            viewer->update(0.01);
            frame();
        }
    }
    const ImDrawData* dd = ImGui::GetDrawData();
    ASSERT_NE(dd, nullptr);
    EXPECT_GT(dd->TotalVtxCount, 0);
}

TEST_F(PanelsTest, TheRenderPanelShowsTheEstimatorAndTheSamplePointsOfAPixel) {
    // The defaults' estimator, in the progress line and the Estimator header; an edit shows at once.
    frame();
    std::string text = windowText([&] { drawRenderPanel(*viewer, ui); });
    EXPECT_NE(text.find("spp, sobol sampler, NEE + MIS, adaptive"), std::string::npos) << text;
    EXPECT_EQ(text.find("adaptive: off"), std::string::npos) << text;
    EXPECT_NE(text.find("estimator: sobol sampler, NEE + MIS"), std::string::npos) << text;
    EXPECT_NE(text.find("pixel (16, 9) (centre): samples 0-63, dimensions 0-1"), std::string::npos) << text;
    ASSERT_TRUE(viewer->document().set("render.sampler", "\"zsobol\""));
    ASSERT_TRUE(viewer->document().set("render.nee", "false"));
    ui.samplePoints.pair = SamplePair::Light;
    ui.samplePoints.bounce = 1;
    ui.samplePoints.count = 16;
    text = windowText([&] { drawRenderPanel(*viewer, ui); });
    EXPECT_NE(text.find("estimator: zsobol sampler, BSDF sampling only"), std::string::npos) << text;
    EXPECT_NE(text.find("samples 0-15, dimensions 16-17"), std::string::npos) << text;
    EXPECT_EQ(ui.samplePoints.sampler, SamplerKind::ZSobol);
    // zsobol lays out exactly spp samples per pixel: the adaptive switch is greyed and says why.
    EXPECT_NE(text.find("adaptive: off, the sobol or independent sampler takes it"), std::string::npos) << text;
    EXPECT_EQ(text.find(", adaptive"), std::string::npos) << text;
    // The estimator's stages: a widget each, and those not at their default in the label.
    for (const char* key : {"diffuse_sampling", "ggx_sampling", "light_selection", "light_sampling", "accel"})
        EXPECT_NE(text.find(key), std::string::npos) << key << " has no widget: " << text;
    ASSERT_TRUE(viewer->document().set("render.diffuse_sampling", "\"uniform\""));
    ASSERT_TRUE(viewer->document().set("render.accel", "\"boxes\""));
    text = windowText([&] { drawRenderPanel(*viewer, ui); });
    EXPECT_NE(text.find("estimator: zsobol sampler, BSDF sampling only, diffuse_sampling uniform, accel boxes"),
              std::string::npos) << text;
}

// The samples view's panel says what its colours count and whether the render spreads them.
TEST_F(PanelsTest, TheDebugPanelExplainsTheSamplesView) {
    viewer->setDebugView(DebugView::Samples);
    for (int i = 0; i < 3; ++i) frame();
    ASSERT_TRUE(viewer->tracer()->adaptive());
    std::string text = windowText([&] { drawDebugPanel(*viewer, ui); });
    EXPECT_NE(text.find("samples per pixel so far"), std::string::npos) << text;
    EXPECT_NE(text.find("adaptive: "), std::string::npos) << text;
    ASSERT_TRUE(viewer->document().set("render.adaptive", "false"));
    frame();
    text = windowText([&] { drawDebugPanel(*viewer, ui); });
    EXPECT_NE(text.find("even spreading: every pixel holds the same samples"), std::string::npos) << text;
}

} // namespace
} // namespace raylab::ui
