#pragma once
// What passes between the GLFW window and the viewer: the input callbacks' events, the script's
// window operations and key presses, and the finished frame as a PNG.
#include "app/script_runner.h"
#include "app/ui_state.h"
#include "app/viewer.h"
#include "script/key_actions.h"

#include <string>
#include <vector>

struct GLFWwindow;

namespace raylab::ui {

// What the window's callbacks collect between frames (ImGui's GLFW backend chains to these).
struct WindowEvents {
    std::vector<std::string> drops;
    bool input = false;   // any key, mouse or window event since the last UI frame
};

// Points the window at `events` and installs the callbacks; call before ImGui's backend, which
// chains to them.
void installInputCallbacks(GLFWwindow* window, WindowEvents& events);
// A key or mouse button held in ImGui's view of the input.
bool anyInputHeld();

class WindowHost : public ScriptHost {
public:
    explicit WindowHost(GLFWwindow* w) : window_(w) {}
    void resizeWindow(int width, int height) override;
    // The script's `drop`: the very callback GLFW calls for a drop on the window.
    void dropFile(const std::string& path) override;

private:
    GLFWwindow* window_;
};

// The script's `key` (ui.pendingKey): its key, with Ctrl when the action wants it, down for
// ui.pendingKeyFrames frames and up the next, as GLFW's key events would leave them; a camera key
// first gives the viewport the keyboard, as a click into it would. Call before ImGui's NewFrame.
class ScriptKeys {
public:
    void update(UiState& ui, Log& log);

private:
    int key_ = keycode::kNone;   // held down by the script
    bool ctrl_ = false;          // with Ctrl
    int framesLeft_ = 0;
};

// The finished frame (before the swap) to a PNG; logs where the traced image lies in it.
bool saveWindow(GLFWwindow* window, const std::string& path, Viewer& viewer, const UiState& ui);

} // namespace raylab::ui
