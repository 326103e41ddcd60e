#include "glfw_context.h"

#include <glad/gl.h>
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

namespace raylab::ui {
namespace {
std::string glfwReason() {
    const char* what = nullptr;
    glfwGetError(&what);
    return what ? what : "unknown reason";
}
} // namespace

GlfwContext::GlfwContext(int width, int height, const char* title, bool visible) {
    if (!glfwInit()) throw std::runtime_error("cannot start GLFW: " + glfwReason() + " (is DISPLAY set?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
    if (!window_) {
        const std::string why = glfwReason();
        glfwTerminate();
        throw std::runtime_error("cannot open an OpenGL 4.5 core window: " + why);
    }
    glfwMakeContextCurrent(window_);
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw std::runtime_error("cannot load OpenGL 4.5 entry points");
    }
}

GlfwContext::~GlfwContext() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::string GlfwContext::description() const { return "glfw | " + currentGlDescription(); }

void GlfwContext::makeCurrent() { glfwMakeContextCurrent(window_); }

} // namespace raylab::ui
