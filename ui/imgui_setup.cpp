#include "imgui_setup.h"

#include "panels/markdown_view.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

namespace raylab::ui {

ImGuiSetup::ImGuiSetup(GLFWwindow* window, const std::string& iniPath) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = iniPath.empty() ? nullptr : iniPath.c_str();
    ImGui::StyleColorsDark();
    // Panels do not overlap in the default layout: opaque backgrounds cost llvmpipe less to draw.
    ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 1.0f;
    loadLessonFonts();   // the Lesson panel's fonts (before the backend builds the font texture)
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450 core");
}

ImGuiSetup::~ImGuiSetup() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

} // namespace raylab::ui
