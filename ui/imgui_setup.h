#pragma once
// Dear ImGui on the viewer's GLFW window: the context, the layout file, the style, the lesson
// fonts and the GLFW + OpenGL 3 backends, for as long as this object lives.
#include <string>

struct GLFWwindow;

namespace raylab::ui {

class ImGuiSetup {
public:
    // iniPath "" keeps no layout file; the string must outlive this object (ImGui keeps the pointer).
    ImGuiSetup(GLFWwindow* window, const std::string& iniPath);
    ~ImGuiSetup();
    ImGuiSetup(const ImGuiSetup&) = delete;
    ImGuiSetup& operator=(const ImGuiSetup&) = delete;
};

} // namespace raylab::ui
