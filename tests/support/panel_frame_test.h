#pragma once
// A fixture for the viewer's panels in ImGui frames without a window (as imgui's example_null
// does): font atlas built, display size set, NewFrame/Render; the viewer runs the default scene at
// 32×18 on the headless context. frame() draws the whole workspace as the window loop does.
#include "panels/panels.h"

#include "render/render_helpers.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <memory>

namespace raylab::test {

class PanelFrameTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(1280, 800);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
        viewer = std::make_unique<ui::Viewer>(log);
        ASSERT_TRUE(viewer->openScene(scenePath("default.json")));
        ASSERT_TRUE(viewer->set("render.width", "32"));
        ASSERT_TRUE(viewer->set("render.height", "18"));
    }
    void TearDown() override {
        viewer.reset();
        ImGui::DestroyContext();
    }
    void frame() {
        ImGui::NewFrame();
        ui::applyUiScale(ui);
        ui::presenterKeys(ui);
        ui::drawWorkspace(*viewer, ui, 1280, 800);
        ImGui::Render();
    }
    ui::Log log{false};
    ui::UiState ui;
    std::unique_ptr<ui::Viewer> viewer;
};

} // namespace raylab::test
