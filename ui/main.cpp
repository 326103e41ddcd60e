// raylab: the interactive viewer. The path tracer (the renderer core raylab-render uses) inside an
// ImGui workspace: `raylab [SCENE] [--script FILE] ...`, see --help.
#include "app/log.h"
#include "app_cli.h"
#include "glfw_context.h"
#include "imgui_setup.h"
#include "viewer_loop.h"
#include "window_io.h"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <memory>

using namespace raylab::ui;

int main(int argc, char** argv) {
    AppOptions options;
    if (const std::optional<int> exit = parseCommandLine(argc, argv, options)) return *exit;
    std::unique_ptr<GlfwContext> context;
    try {
        context = std::make_unique<GlfwContext>(options.windowSize[0], options.windowSize[1], "raylab");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab: error: %s\n", e.what());
        return 1;
    }
    glfwSwapInterval(options.vsync ? 1 : 0);
    WindowEvents events;
    installInputCallbacks(context->window(), events);   // before ImGui's backend, which chains to them
    const ImGuiSetup imgui(context->window(), options.iniPath);
    Log log;
    log.info("OpenGL: " + context->description());
    ViewerLoop loop(context->window(), events, options, log);
    return loop.run();
}
