#include "viewer_loop.h"

#include "app/convergence_watch.h"
#include "panels/panels.h"
#include "presenter_window.h"

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <cstdio>
#include <filesystem>

namespace raylab::ui {

namespace fs = std::filesystem;

ViewerLoop::ViewerLoop(GLFWwindow* window, WindowEvents& events, AppOptions& options, Log& log)
    : window_(window), events_(events), options_(options), log_(log), viewer_(log), host_(window),
      pacer_(options.targetFrameMs * 1e-3) {
    installUiScaleSettings(ui_);
    const ImGuiIO& io = ImGui::GetIO();
    if (io.IniFilename) ImGui::LoadIniSettingsFromDisk(io.IniFilename);   // now, so --ui-scale wins
    if (options_.uiScale > 0.0f) ui_.uiScale = options_.uiScale;
    if (!options_.language.empty()) ui_.lesson.setLanguage(options_.language);   // checked by the command line
    if (!options_.lessonPath.empty() && !ui_.lesson.open(options_.lessonPath)) {
        ui_.showTeach = true;
        ui_.teachTab = 0;
        log_.info("lesson " + ui_.lesson.lesson().title);
    }
    ui_.presenter.classMode = options_.classMode;
    ui_.presenter.show = options_.presenterWindow;
    // Scripted runs take screenshots: no tooltip where the (unmoved) pointer happens to rest.
    if (options_.script) ui_.pixelTooltip = false;
    openFirstScene();
    openExercise();
}

void ViewerLoop::openExercise() {
    if (options_.exercise.empty()) return;
    ui_.exercise.load(exerciseDirectory(), options_.exerciseDir);
    const auto& all = ui_.exercise.exercises();
    for (int i = 0; i < int(all.size()); ++i)
        if (all[std::size_t(i)].name == options_.exercise) ui_.exercise.select(viewer_, i);
    ui_.showTeach = true;
    ui_.teachTab = 3;
    log_.info("exercise " + options_.exercise + ": " + ui_.exercise.pupilFile().string());
}

void ViewerLoop::openFirstScene() {
    const std::string& scene = options_.scenePath;
    if (scene.empty()) return;
    ui_.openPath = scene;
    ui_.savePath = (fs::path(scene).parent_path() / (fs::path(scene).stem().string() + "-edited.json")).string();
    viewer_.setResolutionScale(options_.scale);
    if (!viewer_.openScene(scene)) return;
    for (const std::string& s : options_.sets) {
        const auto eq = s.find('=');
        if (eq == std::string::npos) log_.error("--set " + s + ": expected KEY=VALUE");
        else viewer_.document().set(s.substr(0, eq), s.substr(eq + 1));
    }
}

bool ViewerLoop::runScripts(int frame) {
    if (auto steps = ui_.lesson.takeScript()) {
        stepScript_.emplace(std::move(*steps), options_.scriptTimeout);
        stepScript_->markLessonStep();
    }
    if (stepScript_ && !stepScript_->step(viewer_, ui_, host_, glfwGetTime())) stepScript_.reset();
    ui_.stepScriptRunning = stepScript_.has_value();
    std::optional<ScriptRunner>& script = options_.script;
    if (script && frame >= 2 && !script->step(viewer_, ui_, host_, glfwGetTime())) {
        exitCode_ = script->exitCode();
        return false;
    }
    return true;
}

double ViewerLoop::waitWhileIdle(int frame) {
    // Idle (no input, nothing held, no script): keep tracing in short slices, watching for input,
    // until there is a new image to show or a quarter second has passed. The UI then costs
    // nothing while the user watches the image converge, and still answers at once.
    const bool idle = !options_.continuous && !options_.script && !ui_.split.on() && !stepScript_ && !events_.input &&
                      !anyInputHeld() && frame > 2;
    events_.input = false;
    if (!idle) return 0.0;
    const double idleStart = glfwGetTime();
    while (!viewer_.needsDisplay() && !viewer_.converged() && !viewer_.paused() && glfwGetTime() - idleStart < 0.25) {
        viewer_.update(0.004);
        glfwPollEvents();
        if (events_.input || glfwWindowShouldClose(window_)) break;
    }
    if (viewer_.converged() || viewer_.paused()) glfwWaitEventsTimeout(0.25);   // nothing to trace: sleep
    return glfwGetTime() - idleStart;
}

double ViewerLoop::drawFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    scriptKeys_.update(ui_, log_);
    ImGui::NewFrame();
    shortcutKeys(viewer_, ui_);
    applyUiScale(ui_);
    presenterKeys(ui_);
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    drawWorkspace(viewer_, ui_, float(fw), float(fh));
    ImGui::Render();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    glClearColor(0.09f, 0.09f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const double drawStart = glfwGetTime();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (options_.reportFrames) glFinish();   // so the draw is timed here, not in the swap
    const double drawMs = (glfwGetTime() - drawStart) * 1e3;
    if (!ui_.pendingScreenshot.empty()) {
        saveWindow(window_, ui_.pendingScreenshot, viewer_, ui_);
        ui_.pendingScreenshot.clear();
    }
    return drawMs;
}

int ViewerLoop::run() {
    double last = glfwGetTime();
    for (int frame = 0; !glfwWindowShouldClose(window_); ++frame) {
        glfwPollEvents();
        for (const std::string& p : events_.drops) {
            ui_.openPath = p;
            viewer_.openScene(p);
        }
        events_.drops.clear();
        viewer_.pollFileChanges();
        if (!runScripts(frame)) break;
        if (ui_.split.on()) ui_.split.update(viewer_, pacer_.traceBudget());   // A/B split screen traces instead
        else viewer_.update(pacer_.traceBudget());
        watchConvergence(viewer_, ui_);
        const double idleSeconds = waitWhileIdle(frame);
        const double drawMs = drawFrame();
        const double swapStart = glfwGetTime();
        glfwSwapBuffers(window_);
        drawPresenterWindow();
        const double t = glfwGetTime();
        if (frame >= options_.skipFrames) {
            times_.ms.push_back((t - last) * 1e3);
            times_.traceMs.push_back(viewer_.stats().frameTraceMs);
            times_.displayMs.push_back(viewer_.stats().frameDisplayMs);
            times_.drawMs.push_back(drawMs);
            times_.swapMs.push_back((t - swapStart) * 1e3);
            if (!options_.frameLog.empty()) times_.residentMiB.push_back(residentMiB());
        }
        pacer_.frameDone(t - last - idleSeconds, viewer_.stats().frameTraceMs * 1e-3);
        last = t;
        if (options_.maxFrames > 0 && frame + 1 >= options_.maxFrames) break;
    }
    if (options_.reportFrames) printReport();
    if (!options_.frameLog.empty()) times_.write(options_.frameLog);
    return exitCode_;
}

void ViewerLoop::drawPresenterWindow() {
    ui_.presenter.ownWindow = options_.presenterWindow;
    if (!options_.presenterWindow) return;
    if (ui_.presenter.show && !presenter_) {
        try {
            presenter_ = std::make_unique<PresenterWindow>(window_);
            log_.info("presenter window opened");
        } catch (const std::exception& e) {
            log_.error(std::string(e.what()) + ": the presenter view is a panel of this window (F2)");
            options_.presenterWindow = ui_.presenter.ownWindow = false;
            return;
        }
    }
    if (presenter_ && (!ui_.presenter.show || presenter_->closeRequested())) {
        presenter_.reset();
        ui_.presenter.show = false;
        log_.info("presenter window closed");
    }
    if (presenter_) presenter_->draw(ui_);
}

ViewerLoop::~ViewerLoop() = default;

void ViewerLoop::printReport() const {
    times_.report();
    const PathTracer* t = viewer_.tracer();
    const double traced = viewer_.stats().traceSeconds;
    std::printf("target %.1f ms/frame; tracing budget now %.2f ms; %llu spp traced in %.2f s of tracing "
                "(%.2f Mpaths/s); image %d x %d\n",
                options_.targetFrameMs, pacer_.traceBudget() * 1e3, (unsigned long long)(t ? t->samplesPerPixel() : 0), traced,
                t && traced > 0 ? double(t->pathsTraced()) / traced * 1e-6 : 0.0, viewer_.imageWidth(), viewer_.imageHeight());
}

} // namespace raylab::ui
