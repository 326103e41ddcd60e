#include "presenter_window.h"

#include "panels/panels.h"

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <stdexcept>
#include <string>

namespace raylab::ui {
namespace {

// GLFW calls these during glfwPollEvents, while the main window's ImGui context is current: each
// forwards to the backend with the presenter's context current.
ImGuiContext* contextOf(GLFWwindow* w) { return static_cast<ImGuiContext*>(glfwGetWindowUserPointer(w)); }

template <typename F>
void withContext(GLFWwindow* w, F&& f) {
    ImGuiContext* previous = ImGui::GetCurrentContext();
    ImGui::SetCurrentContext(contextOf(w));
    f();
    ImGui::SetCurrentContext(previous);
}

void installCallbacks(GLFWwindow* w) {
    glfwSetWindowFocusCallback(w, [](GLFWwindow* win, int focused) {
        withContext(win, [&] { ImGui_ImplGlfw_WindowFocusCallback(win, focused); });
    });
    glfwSetCursorEnterCallback(w, [](GLFWwindow* win, int entered) {
        withContext(win, [&] { ImGui_ImplGlfw_CursorEnterCallback(win, entered); });
    });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int mods) {
        withContext(win, [&] { ImGui_ImplGlfw_MouseButtonCallback(win, button, action, mods); });
    });
    glfwSetScrollCallback(w, [](GLFWwindow* win, double x, double y) {
        withContext(win, [&] { ImGui_ImplGlfw_ScrollCallback(win, x, y); });
    });
    glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int scancode, int action, int mods) {
        withContext(win, [&] { ImGui_ImplGlfw_KeyCallback(win, key, scancode, action, mods); });
    });
    glfwSetCharCallback(w, [](GLFWwindow* win, unsigned int c) {
        withContext(win, [&] { ImGui_ImplGlfw_CharCallback(win, c); });
    });
}

bool pressed(ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false); }

} // namespace

PresenterWindow::PresenterWindow(GLFWwindow* main) : main_(main), mainContext_(ImGui::GetCurrentContext()) {
    glfwWindowHint(GLFW_VISIBLE, GLFW_TRUE);
    window_ = glfwCreateWindow(720, 800, "raylab: presenter", nullptr, main);
    glfwMakeContextCurrent(main_);
    if (!window_) {
        const char* what = nullptr;
        glfwGetError(&what);
        throw std::runtime_error(std::string("cannot open the presenter window: ") + (what ? what : "unknown reason"));
    }
    // On a second monitor when there is one: the projector shows the main window.
    int monitors = 0;
    GLFWmonitor** all = glfwGetMonitors(&monitors);
    if (monitors > 1) {
        int x = 0, y = 0;
        glfwGetMonitorPos(all[1], &x, &y);
        glfwSetWindowPos(window_, x + 40, y + 40);
    }
    ImFontAtlas* fonts = ImGui::GetIO().Fonts;
    mainFontTexture_ = fonts->TexID;
    context_ = ImGui::CreateContext(fonts);   // the same fonts (the lesson fonts are pointers into this atlas)
    glfwSetWindowUserPointer(window_, context_);
    ImGui::SetCurrentContext(context_);
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(0);
    ImGui_ImplGlfw_InitForOpenGL(window_, false);
    ImGui_ImplOpenGL3_Init("#version 450 core");
    installCallbacks(window_);
    glfwMakeContextCurrent(main_);
    ImGui::SetCurrentContext(mainContext_);
}

PresenterWindow::~PresenterWindow() {
    glfwMakeContextCurrent(window_);
    ImGui::SetCurrentContext(context_);
    ImGui_ImplOpenGL3_Shutdown();   // deletes this window's copy of the font texture
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(mainContext_);
    ImGui::GetIO().Fonts->SetTexID(mainFontTexture_);
    glfwMakeContextCurrent(main_);
    glfwDestroyWindow(window_);
}

bool PresenterWindow::closeRequested() const { return glfwWindowShouldClose(window_) != 0; }

void PresenterWindow::draw(UiState& ui) {
    glfwMakeContextCurrent(window_);
    ImGui::SetCurrentContext(context_);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (pressed(ImGuiKey_PageDown) || pressed(ImGuiKey_RightArrow) || pressed(ImGuiKey_Space)) ui.lesson.next();
    if (pressed(ImGuiKey_PageUp) || pressed(ImGuiKey_LeftArrow)) ui.lesson.previous();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    ImGui::GetIO().FontGlobalScale = ui.uiScale;
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(float(w), float(h)));
    ImGui::Begin("Presenter", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    drawPresenterPanel(ui);
    ImGui::End();
    ImGui::Render();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, w, h);
    glClearColor(0.09f, 0.09f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window_);
    glfwMakeContextCurrent(main_);
    ImGui::SetCurrentContext(mainContext_);
}

} // namespace raylab::ui
