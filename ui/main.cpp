// raylab: the interactive viewer. The path tracer (the renderer core raylab-render uses) inside an
// ImGui workspace: `raylab [SCENE] [--script FILE] ...`, see --help.
#include "app/frame_pacer.h"
#include "app/log.h"
#include "app/screenshot.h"
#include "script/script.h"
#include "app/script_runner.h"
#include "app/viewer.h"
#include "app/convergence_watch.h"
#include "lesson/lesson.h"
#include "glfw_context.h"
#include "gl/shader_source.h"
#include "panels/markdown_view.h"
#include "panels/panels.h"

#include <CLI/CLI.hpp>
#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace raylab;
using namespace raylab::ui;

namespace {

// What the window's callbacks collect between frames (ImGui's GLFW backend chains to these).
struct WindowEvents {
    std::vector<std::string> drops;
    bool input = false;   // any key, mouse or window event since the last UI frame
};

WindowEvents& events(GLFWwindow* window) { return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window)); }

void onDrop(GLFWwindow* window, int count, const char** paths) {
    for (int i = 0; i < count; ++i) events(window).drops.emplace_back(paths[i]);
    events(window).input = true;
}

void installInputCallbacks(GLFWwindow* w) {
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

// The script's `key` names (src/script/script.h) as GLFW key codes: ImGui's GLFW backend indexes
// io.KeysDown by them, so a scripted key goes through the same handling as a pressed one.
int scriptKeyCode(const std::string& name) {
    static const std::map<std::string, int> codes = {
        {"page-down", GLFW_KEY_PAGE_DOWN}, {"page-up", GLFW_KEY_PAGE_UP}, {"space", GLFW_KEY_SPACE},
        {"r", GLFW_KEY_R}, {"f5", GLFW_KEY_F5}, {"f9", GLFW_KEY_F9}, {"f12", GLFW_KEY_F12}};
    const auto it = codes.find(name);
    return it == codes.end() ? -1 : it->second;
}

class WindowHost : public ScriptHost {
public:
    explicit WindowHost(GLFWwindow* w) : window_(w) {}
    void resizeWindow(int width, int height) override { glfwSetWindowSize(window_, width, height); }
    // The script's `drop`: the very callback GLFW calls for a drop on the window.
    void dropFile(const std::string& path) override {
        const char* paths[] = {path.c_str()};
        onDrop(window_, 1, paths);
    }

private:
    GLFWwindow* window_;
};

// The finished frame (before the swap) to a PNG.
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

fs::path defaultScene() {
    const fs::path candidate = shaderDirectory() / ".." / "scenes" / "default.json";
    std::error_code ec;
    return fs::exists(candidate, ec) ? fs::weakly_canonical(candidate, ec) : fs::path();
}

struct FrameTimes {
    std::vector<double> ms, traceMs, displayMs, drawMs, swapMs;
    static double mean(const std::vector<double>& v) {
        return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
    }
    void report() const {
        if (ms.empty()) return;
        std::vector<double> s = ms;
        std::sort(s.begin(), s.end());
        const double m = mean(s);
        const auto over50 = s.end() - std::upper_bound(s.begin(), s.end(), 50.0);
        std::printf("frames %zu: mean %.2f ms (%.1f fps), median %.2f ms, p95 %.2f ms, max %.2f ms, %td over 50 ms\n", s.size(),
                    m, 1000.0 / m, s[s.size() / 2], s[std::min(s.size() - 1, s.size() * 95 / 100)], s.back(), over50);
        double slowestTrace = 0.0;
        for (double t : traceMs) slowestTrace = std::max(slowestTrace, t);
        std::printf("slowest tracing in one frame: %.2f ms\n", slowestTrace);
        std::printf("per frame (means): trace %.2f ms, display pass %.2f ms, UI draw %.2f ms, swap %.2f ms, other %.2f ms\n",
                    mean(traceMs), mean(displayMs), mean(drawMs), mean(swapMs),
                    m - mean(traceMs) - mean(displayMs) - mean(drawMs) - mean(swapMs));
    }
};

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"raylab: the interactive path tracer (GLFW + ImGui viewer)"};
    std::string scenePath;
    std::string scriptPath;
    std::string iniPath = "imgui.ini";
    std::vector<int> windowSize{1280, 800};
    float scale = 1.0f;
    std::vector<std::string> sets;
    double targetFrameMs = 30.0;
    int maxFrames = 0;
    int skipFrames = 30;
    double scriptTimeout = 300.0;
    bool reportFrames = false;
    bool vsync = false;
    bool continuous = false;
    std::string lessonPath;
    float uiScale = 0.0f;
    app.add_option("scene", scenePath, "Scene file (default: scenes/default.json)");
    app.add_option("--script", scriptPath, "Automation script: one command a line (see src/script/script.h)");
    app.add_option("--script-timeout", scriptTimeout, "Seconds before a script that has not quit fails")->capture_default_str();
    app.add_option("--window", windowSize, "Window size W H")->expected(2)->capture_default_str();
    app.add_option("--scale", scale, "Resolution scale of the traced image")->check(CLI::Range(0.125, 2.0))->capture_default_str();
    app.add_option("--set", sets, "KEY=VALUE scene override after loading (repeatable)");
    app.add_option("--ini", iniPath, "Layout file ('' = do not save the layout)")->capture_default_str();
    app.add_option("--frame-time", targetFrameMs, "Target milliseconds per UI frame; tracing gets what the UI leaves")
        ->check(CLI::Range(1.0, 1000.0))->capture_default_str();
    app.add_option("--frames", maxFrames, "Quit after this many frames (benchmarks)");
    app.add_option("--skip-frames", skipFrames, "Frames left out of --report-frames (warm-up)")->capture_default_str();
    app.add_flag("--report-frames", reportFrames, "Print frame-time statistics at exit");
    app.add_flag("--vsync", vsync, "Wait for the display's refresh");
    app.add_flag("--continuous", continuous,
                 "Redraw the UI every frame even when idle (by default, with no input the UI redraws when a "
                 "pass completes or every 0.25 s, and tracing gets the time in between)");
    app.add_option("--lesson", lessonPath, "Open a lesson (lessons/NN-topic.md) in the Teach window; its scene unless SCENE is given");
    app.add_option("--ui-scale", uiScale, "UI scale for projectors (default: as last time, from the layout file)")
        ->check(CLI::Range(double(kMinUiScale), double(kMaxUiScale)));
    CLI11_PARSE(app, argc, argv);
    if (!lessonPath.empty()) {
        try {
            const Lesson lesson = loadLesson(lessonPath);   // fail before a window opens
            if (scenePath.empty()) scenePath = lesson.scenePath.string();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "raylab: %s\n", e.what());
            return 1;
        }
    }

    std::optional<ScriptRunner> script;
    if (!scriptPath.empty()) {
        try {
            script.emplace(loadScript(scriptPath), scriptTimeout);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "raylab: %s\n", e.what());
            return 1;
        }
    }
    if (scenePath.empty()) scenePath = defaultScene().string();

    std::unique_ptr<GlfwContext> context;
    try {
        context = std::make_unique<GlfwContext>(windowSize[0], windowSize[1], "raylab");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab: error: %s\n", e.what());
        return 1;
    }
    GLFWwindow* window = context->window();
    glfwSwapInterval(vsync ? 1 : 0);
    WindowEvents windowEvents;
    glfwSetWindowUserPointer(window, &windowEvents);
    installInputCallbacks(window);   // before ImGui's backend, which chains to them

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

    Log log;
    log.info("OpenGL: " + context->description());
    int exitCode = 0;
    {
        Viewer viewer(log);
        UiState ui;
        installUiScaleSettings(ui);
        if (io.IniFilename) ImGui::LoadIniSettingsFromDisk(io.IniFilename);   // now, so --ui-scale wins
        if (uiScale > 0.0f) ui.uiScale = uiScale;
        if (!lessonPath.empty() && !ui.lesson.open(lessonPath)) {
            ui.showTeach = true;
            ui.teachTab = 0;
            log.info("lesson " + ui.lesson.lesson().title);
        }
        std::optional<ScriptRunner> stepScript;   // the lesson step being applied
        // Scripted runs take screenshots: no tooltip where the (unmoved) pointer happens to rest.
        if (script) ui.pixelTooltip = false;
        if (!scenePath.empty()) {
            ui.openPath = scenePath;
            ui.savePath = (fs::path(scenePath).parent_path() / (fs::path(scenePath).stem().string() + "-edited.json")).string();
            viewer.setResolutionScale(scale);
            if (viewer.openScene(scenePath))
                for (const std::string& s : sets) {
                    const auto eq = s.find('=');
                    if (eq == std::string::npos) log.error("--set " + s + ": expected KEY=VALUE");
                    else viewer.set(s.substr(0, eq), s.substr(eq + 1));
                }
        }
        WindowHost host(window);
        FrameTimes times;
        FramePacer pacer(targetFrameMs * 1e-3);
        double last = glfwGetTime();
        for (int frame = 0; !glfwWindowShouldClose(window); ++frame) {
            glfwPollEvents();
            for (const std::string& p : windowEvents.drops) {
                ui.openPath = p;
                viewer.openScene(p);
            }
            windowEvents.drops.clear();
            viewer.pollFileChanges();
            if (auto steps = ui.lesson.takeScript()) {
                stepScript.emplace(std::move(*steps), scriptTimeout);
                stepScript->markLessonStep();
            }
            if (stepScript && !stepScript->step(viewer, ui, host, glfwGetTime())) stepScript.reset();
            ui.stepScriptRunning = stepScript.has_value();
            if (script && frame >= 2 && !script->step(viewer, ui, host, glfwGetTime())) {
                exitCode = script->exitCode();
                break;
            }
            if (ui.split.on()) ui.split.update(viewer, pacer.traceBudget());   // A/B split screen traces instead
            else viewer.update(pacer.traceBudget());
            watchConvergence(viewer, ui);
            // Idle (no input, nothing held, no script): keep tracing in short slices, watching for
            // input, until there is a new image to show or a quarter second has passed. The UI then
            // costs nothing while the user watches the image converge, and still answers at once.
            const bool idle = !continuous && !script && !ui.split.on() && !stepScript && !windowEvents.input && !anyInputHeld() && frame > 2;
            windowEvents.input = false;
            double idleSeconds = 0.0;
            if (idle) {
                const double idleStart = glfwGetTime();
                while (!viewer.needsDisplay() && !viewer.converged() && !viewer.paused() &&
                       glfwGetTime() - idleStart < 0.25) {
                    viewer.update(0.004);
                    glfwPollEvents();
                    if (windowEvents.input || glfwWindowShouldClose(window)) break;
                }
                if (viewer.converged() || viewer.paused()) glfwWaitEventsTimeout(0.25);   // nothing to trace: sleep
                idleSeconds = glfwGetTime() - idleStart;
            }

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            // The script's `key`: down for one frame, up the next, as GLFW's key events would leave it.
            static int scriptKey = -1;
            if (scriptKey >= 0) io.KeysDown[scriptKey] = false;
            scriptKey = -1;
            if (!ui.pendingKey.empty()) {
                scriptKey = scriptKeyCode(ui.pendingKey);
                if (scriptKey >= 0) io.KeysDown[scriptKey] = true;
                else log.error("script: no key code for key '" + ui.pendingKey + "'");
                ui.pendingKey.clear();
            }
            ImGui::NewFrame();
            applyUiScale(ui);
            presenterKeys(ui);
            if (!io.WantTextInput) {
                if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) ui.pendingScreenshot = ui.screenshotPath;
                if (ImGui::IsKeyPressed(GLFW_KEY_F9, false)) viewer.exportRender(ui.exportPath);
                if (ImGui::IsKeyPressed(GLFW_KEY_F5, false) && viewer.reloadShaders()) log.info("reloaded the shaders (F5)");
                if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false) && !(ui.teachFocused && ui.lesson.isOpen()))
                    viewer.setPaused(!viewer.paused());   // in the Teach window Space is the next step
                if (ImGui::IsKeyPressed(GLFW_KEY_F1, false)) ui.showTeach = !ui.showTeach;
                if (ImGui::IsKeyPressed(GLFW_KEY_R, false) && !io.KeyCtrl) viewer.resetAccumulation();
                if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S, false) && !ui.savePath.empty()) viewer.saveScene(ui.savePath);
            }
            int fw = 0, fh = 0;
            glfwGetFramebufferSize(window, &fw, &fh);
            drawWorkspace(viewer, ui, float(fw), float(fh));
            ImGui::Render();
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, fw, fh);
            glClearColor(0.09f, 0.09f, 0.1f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            const double drawStart = glfwGetTime();
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            if (reportFrames) glFinish();   // so the draw is timed here, not in the swap
            const double drawMs = (glfwGetTime() - drawStart) * 1e3;
            if (!ui.pendingScreenshot.empty()) {
                saveWindow(window, ui.pendingScreenshot, viewer, ui);
                ui.pendingScreenshot.clear();
            }
            const double swapStart = glfwGetTime();
            glfwSwapBuffers(window);
            const double t = glfwGetTime();
            if (frame >= skipFrames) {
                times.ms.push_back((t - last) * 1e3);
                times.traceMs.push_back(viewer.stats().frameTraceMs);
                times.displayMs.push_back(viewer.stats().frameDisplayMs);
                times.drawMs.push_back(drawMs);
                times.swapMs.push_back((t - swapStart) * 1e3);
            }
            pacer.frameDone(t - last - idleSeconds, viewer.stats().frameTraceMs * 1e-3);
            last = t;
            if (maxFrames > 0 && frame + 1 >= maxFrames) break;
        }
        if (reportFrames) {
            times.report();
            const PathTracer* t = viewer.tracer();
            const double traced = viewer.stats().traceSeconds;
            std::printf("target %.1f ms/frame; tracing budget now %.2f ms; %llu spp traced in %.2f s of tracing "
                        "(%.2f Mpaths/s); image %d x %d\n",
                        targetFrameMs, pacer.traceBudget() * 1e3, (unsigned long long)(t ? t->samplesPerPixel() : 0), traced,
                        t && traced > 0 ? double(t->pathsTraced()) / traced * 1e-6 : 0.0, viewer.imageWidth(), viewer.imageHeight());
        }
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return exitCode;
}
