#pragma once
// The presenter view in a window of its own (--presenter-window): for the teacher's screen while
// the main window is on the projector. It shares the main window's GL objects and font atlas and
// has its own ImGui context, whose input callbacks switch to that context first (ImGui's GLFW
// backend keeps its state per context). PageDown/PageUp, the arrows and Space step the lesson here too.
#include "app/ui_state.h"

struct GLFWwindow;
struct ImGuiContext;

namespace raylab::ui {

class PresenterWindow {
public:
    // Opens the window beside `main` (on a second monitor when there is one); throws
    // std::runtime_error when GLFW cannot. The main window's context and ImGui context stay current.
    explicit PresenterWindow(GLFWwindow* main);
    ~PresenterWindow();
    PresenterWindow(const PresenterWindow&) = delete;
    PresenterWindow& operator=(const PresenterWindow&) = delete;

    // One frame of the presenter view; the main window's contexts are current again afterwards.
    void draw(UiState& ui);
    bool closeRequested() const;

private:
    GLFWwindow* main_;
    GLFWwindow* window_ = nullptr;
    ImGuiContext* mainContext_ = nullptr;
    ImGuiContext* context_ = nullptr;
    void* mainFontTexture_ = nullptr;   // the shared atlas' texture, given back when this window closes
};

} // namespace raylab::ui
