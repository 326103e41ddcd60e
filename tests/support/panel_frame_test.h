#pragma once
// A fixture for the viewer's panels in ImGui frames without a window (as imgui's example_null
// does): font atlas built, display size set, NewFrame/Render; the viewer runs the default scene at
// 32×18 on the headless context. frame() draws the whole workspace as the window loop does;
// windowText() the text a panel draws.
#include "panels/panels.h"

#include "support/viewer_test_base.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <functional>
#include <memory>
#include <string>

namespace raylab::test {

class PanelFrameTest : public ViewerTestBase {
protected:
    void SetUp() override {
        ViewerTestBase::SetUp();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(1280, 800);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
        openSmall("default.json", 32, 18);
    }
    void TearDown() override {
        viewer.reset();
        ImGui::DestroyContext();
    }
    void frame() {
        ImGui::NewFrame();
        ui::shortcutKeys(*viewer, ui);
        ui::applyUiScale(ui);
        ui::presenterKeys(ui);
        ui::drawWorkspace(*viewer, ui, 1280, 800);
        ImGui::Render();
    }
    // A frame in which only `draw` submits windows (ui::drawStatsPanel, ui::drawViewport, ...);
    // returns the text they drew, one line per line, up to the end of the first window that is
    // not a child window: ImGui's log ends there (ImGui::End), and LogToClipboard hands its text
    // to the clipboard, kept here. A tooltip is such a window: the text of its owner up to it.
    std::string windowText(const std::function<void()>& draw) {
        ImGuiIO& io = ImGui::GetIO();
        io.ClipboardUserData = &clipboard_;
        io.SetClipboardTextFn = [](void* user, const char* text) { *static_cast<std::string*>(user) = text; };
        io.GetClipboardTextFn = [](void* user) { return static_cast<std::string*>(user)->c_str(); };
        clipboard_.clear();
        ImGui::NewFrame();
        ImGui::LogToClipboard();
        draw();
        ImGui::LogFinish();   // nothing to do when a window's End finished it
        ImGui::Render();
        return clipboard_;
    }
    // The Lesson panel's text, in a window tall enough for a whole lesson.
    std::string lessonPanelText() {
        return windowText([&] {
            ImGui::SetNextWindowSize(ImVec2(600, 20000));
            ImGui::Begin("lesson");
            ui::drawLessonPanel(*viewer, ui);
            ImGui::End();
        });
    }
    ui::UiState ui;

private:
    std::string clipboard_;
};

} // namespace raylab::test
