#include "window_io.h"

#include "app/screenshot.h"

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace raylab::ui {
namespace {

static_assert(keycode::kSpace == GLFW_KEY_SPACE && keycode::kMinus == GLFW_KEY_MINUS && keycode::k0 == GLFW_KEY_0 &&
              keycode::kEqual == GLFW_KEY_EQUAL && keycode::kR == GLFW_KEY_R && keycode::kS == GLFW_KEY_S &&
              keycode::kPageUp == GLFW_KEY_PAGE_UP && keycode::kPageDown == GLFW_KEY_PAGE_DOWN &&
              keycode::kF1 == GLFW_KEY_F1 && keycode::kF2 == GLFW_KEY_F2 && keycode::kF5 == GLFW_KEY_F5 && keycode::kF9 == GLFW_KEY_F9 &&
              keycode::kF12 == GLFW_KEY_F12 && keycode::kKpSubtract == GLFW_KEY_KP_SUBTRACT &&
              keycode::kKpAdd == GLFW_KEY_KP_ADD && keycode::kLeftControl == GLFW_KEY_LEFT_CONTROL &&
              keycode::kW == GLFW_KEY_W && keycode::kA == GLFW_KEY_A && keycode::kD == GLFW_KEY_D &&
              keycode::kQ == GLFW_KEY_Q && keycode::kE == GLFW_KEY_E && keycode::kRight == GLFW_KEY_RIGHT &&
              keycode::kLeft == GLFW_KEY_LEFT && keycode::kDown == GLFW_KEY_DOWN && keycode::kUp == GLFW_KEY_UP);

WindowEvents& events(GLFWwindow* window) { return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window)); }

void onDrop(GLFWwindow* window, int count, const char** paths) {
    for (int i = 0; i < count; ++i) events(window).drops.emplace_back(paths[i]);
    events(window).input = true;
}

} // namespace

void installInputCallbacks(GLFWwindow* w, WindowEvents& e) {
    glfwSetWindowUserPointer(w, &e);
    glfwSetDropCallback(w, onDrop);
    glfwSetCursorPosCallback(w, [](GLFWwindow* win, double, double) { events(win).input = true; });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int, int, int) { events(win).input = true; });
    glfwSetScrollCallback(w, [](GLFWwindow* win, double, double) { events(win).input = true; });
    glfwSetKeyCallback(w, [](GLFWwindow* win, int, int, int, int) { events(win).input = true; });
    glfwSetCharCallback(w, [](GLFWwindow* win, unsigned) { events(win).input = true; });
    glfwSetWindowSizeCallback(w, [](GLFWwindow* win, int, int) { events(win).input = true; });
    glfwSetWindowFocusCallback(w, [](GLFWwindow* win, int) { events(win).input = true; });
    glfwSetCursorEnterCallback(w, [](GLFWwindow* win, int) { events(win).input = true; });
}

bool anyInputHeld() {
    const ImGuiIO& io = ImGui::GetIO();
    for (bool down : io.KeysDown)
        if (down) return true;
    for (bool down : io.MouseDown)
        if (down) return true;
    return false;
}

void WindowHost::resizeWindow(int width, int height) { glfwSetWindowSize(window_, width, height); }

void WindowHost::dropFile(const std::string& path) {
    const char* paths[] = {path.c_str()};
    onDrop(window_, 1, paths);
}

void ScriptKeys::update(UiState& ui, Log& log) {
    ImGuiIO& io = ImGui::GetIO();
    auto hold = [&io](int key, bool ctrl, bool down) {
        io.KeysDown[key] = down;
        if (ctrl) {
            io.KeysDown[keycode::kLeftControl] = down;
            io.KeyCtrl = down;
        }
    };
    if (key_ != keycode::kNone && --framesLeft_ <= 0) {
        hold(key_, ctrl_, false);
        key_ = keycode::kNone;
    }
    if (ui.pendingKey.empty()) return;
    if (key_ != keycode::kNone) hold(key_, ctrl_, false);
    key_ = keycode::kNone;
    for (const KeyBinding& b : kKeyBindings)
        if (b.name == ui.pendingKey) {
            key_ = b.key;
            ctrl_ = b.ctrl == Ctrl::With;
        }
    for (const CameraKey& k : kCameraKeys)
        if (k.name == ui.pendingKey) {
            key_ = k.key;
            ctrl_ = false;
            ui.focusViewport = true;
        }
    if (key_ == keycode::kNone) {
        log.error("script: no key code for key '" + ui.pendingKey + "'");
    } else {
        hold(key_, ctrl_, true);
        framesLeft_ = std::max(ui.pendingKeyFrames, 1);
    }
    ui.pendingKey.clear();
}

bool saveWindow(GLFWwindow* window, const std::string& path, Viewer& viewer, const UiState& ui) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    std::vector<std::uint8_t> pixels(std::size_t(w) * h * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    try {
        writeRgba8Png(path, w, h, pixels);
    } catch (const std::exception& e) {
        viewer.log().error(e.what());
        return false;
    }
    // Where the image lies in the screenshot, for tests that compare overlays with projections.
    char where[200];
    std::snprintf(where, sizeof where, "screenshot %s (%dx%d; image at %.1f %.1f size %.1f %.1f, %llu spp)", path.c_str(), w, h,
                  double(ui.image.x), double(ui.image.y), double(ui.image.width), double(ui.image.height),
                  (unsigned long long)(viewer.tracer() ? viewer.tracer()->samplesPerPixel() : 0));
    viewer.log().info(where);
    return true;
}

} // namespace raylab::ui
