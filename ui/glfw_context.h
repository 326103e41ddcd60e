#pragma once
// The viewer's GL context: a GLFW window's OpenGL 4.5 core context behind the renderer's GlContext
// interface (src/gl/gl_context.h), with GL loaded by glad through glfwGetProcAddress.
#include "gl/gl_context.h"

struct GLFWwindow;

namespace raylab::ui {

class GlfwContext : public GlContext {
public:
    // Creates the window (hidden when `visible` is false) and makes its context current. Throws
    // std::runtime_error with GLFW's reason.
    GlfwContext(int width, int height, const char* title, bool visible = true);
    ~GlfwContext() override;
    std::string description() const override;
    void makeCurrent() override;
    GLFWwindow* window() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

} // namespace raylab::ui
