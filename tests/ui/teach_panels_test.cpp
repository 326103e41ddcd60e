// The Teach window's tabs in ImGui frames without a window (as panels_test.cpp): a lesson's
// Markdown, the Classroom tab with the split screen on (both sides drawn over the image), and the
// Self-test tab with a report; drawing changes neither the scene nor the lesson's step.
#include "panels/panels.h"

#include "render/render_helpers.h"
#include "support/gl_test.h"
#include "support/panel_frame_test.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

namespace raylab::ui {
namespace {

class TeachPanelsTest : public test::PanelFrameTest {
protected:
    void SetUp() override {
        PanelFrameTest::SetUp();
        ASSERT_TRUE(viewer->document().set("render.spp", "2"));
    }
};

} // namespace

TEST_F(TeachPanelsTest, EveryTabDrawsWithALessonASplitAndAReport) {
    ui.showTeach = true;
    ASSERT_FALSE(ui.lesson.open(std::string(RAYLAB_SOURCE_DIR) + "/lessons/08-microfacets-ggx-fresnel.md").has_value());
    ui.lesson.apply(1);
    ui.lesson.takeScript();   // the window loop would run it; here only the drawing is tested
    const nlohmann::json before = sceneToJson(viewer->scene());
    for (int tab = 0; tab < 3; ++tab) {
        ui.teachTab = tab;
        if (tab == 1) {
            ui.split.addOverride(0, "render.stage", "lambert", viewer->scene());
            ui.split.start(SplitBudget::EqualSamples);
            for (int i = 0; i < 50 && !ui.split.converged(); ++i) ui.split.update(*viewer, 0.01);
        }
        if (tab == 2) {
            ui.selfTest.results.push_back(SelfTestResult{"furnace", true, "max deviation", 1e-7, 0, 1.0, 1e-5, ""});
            ui.selfTest.driver = "test";
        }
        for (int i = 0; i < 3; ++i) frame();
        const ImGuiWindow* teach = ImGui::FindWindowByName("Teach");
        ASSERT_NE(teach, nullptr);
        EXPECT_TRUE(teach->Active);
    }
    EXPECT_EQ(sceneToJson(viewer->scene()), before);
    EXPECT_EQ(ui.lesson.current(), 1);
    EXPECT_TRUE(ui.split.converged());
    ui.uiScale = 2.0f;
    frame();
    EXPECT_FLOAT_EQ(ImGui::GetIO().FontGlobalScale, 2.0f);
    ui.uiScale = 1.0f;
    frame();
    EXPECT_FLOAT_EQ(ImGui::GetIO().FontGlobalScale, 1.0f);
}

} // namespace raylab::ui
