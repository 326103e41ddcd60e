#include "app/script_runner.h"

#include "app/scene_object.h"
#include "app/viewport_click.h"
#include "render/debug_views.h"
#include "script/expectation.h"

#include <algorithm>
#include <string>

namespace raylab::ui {

ScriptRunner::ScriptRunner(std::vector<ScriptCommand> commands, double timeoutSeconds)
    : commands_(std::move(commands)), timeout_(timeoutSeconds) {}

bool ScriptRunner::step(Viewer& viewer, UiState& ui, ScriptHost& host, double now) {
    if (finished_) return false;
    if (start_ < 0.0) start_ = now;
    if (now - start_ > timeout_) {
        viewer.log().error("script: timed out after " + std::to_string(int(timeout_)) + " s at " +
                           (next_ > 0 ? commands_[next_ - 1].text() : std::string("the start")));
        exitCode_ = 2;
        finished_ = true;
        return false;
    }
    if (!lessonStep_ && (ui.stepScriptRunning || ui.lesson.hasPending())) return true;   // a lesson step first
    // Waits of the previous command.
    if (!ui.pendingScreenshot.empty()) return true;
    if (waitFrames_ > 0) {
        --waitFrames_;
        return true;
    }
    if (waitSpp_ >= 0) {
        const bool reached = !viewer.hasScene() ||
                             (ui.split.on() ? ui.split.converged() || ui.split.minSpp() >= std::uint64_t(waitSpp_)
                                            : viewer.converged() || (viewer.tracer() && viewer.tracer()->samplesPerPixel() >=
                                                                                            std::uint64_t(waitSpp_)));
        if (!reached) return true;
        waitSpp_ = -1;
        waitFrames_ = 1;   // one more frame so the display shows the samples
        return true;
    }
    while (next_ < commands_.size()) {
        const ScriptCommand& c = commands_[next_++];
        if (c.name == "quit") {
            exitCode_ = failures_ > 0 ? 1 : 0;
            finished_ = true;
            return false;
        }
        if (!run(c, viewer, ui, host)) {
            ++failures_;
            viewer.log().error("script: " + c.text() + " failed");
        }
        // Commands that change what is drawn let a frame pass before the next one.
        if (waitFrames_ > 0 || waitSpp_ >= 0 || !ui.pendingScreenshot.empty()) return true;
        if (c.name != "set" && c.name != "pause" && c.name != "resume" && c.name != "save" && c.name != "export" &&
            c.name != "inspect-export") {
            waitFrames_ = 1;
            return true;
        }
    }
    exitCode_ = failures_ > 0 ? 1 : 0;
    finished_ = true;
    return false;
}

namespace {

// "selected.KEY" names a key of the selected object ("selected.radius", "selected.transform.
// translation") or of the material it edits ("selected.albedo"), as the Material panel shows them,
// or of the selected light ("selected.intensity"), as the Light panel does.
std::string selectedKey(const Viewer& viewer, const std::string& key) {
    const std::string prefix = "selected.";
    if (key.rfind(prefix, 0) != 0) return key;
    const std::string field = key.substr(prefix.size());
    if (viewer.selection.light() >= 0) return "lights." + std::to_string(viewer.selection.light()) + "." + field;
    if (viewer.selection.object() < 0) return key;
    for (const MaterialParamSpec& p : materialParameters())
        if (p.key == field) return "materials." + std::to_string(viewer.selection.editedMaterial()) + "." + field;
    return "objects." + std::to_string(viewer.selection.object()) + "." + field;
}

} // namespace

bool ScriptRunner::run(const ScriptCommand& c, Viewer& viewer, UiState& ui, ScriptHost& host) {
    const auto& a = c.args;
    const auto num = [&](std::size_t i) { return std::stod(a[i]); };
    if (c.name == "open") return viewer.openScene(a[0]);
    if (c.name == "set") return viewer.document().set(selectedKey(viewer, a[0]), a[1]);
    if (c.name == "click") {
        viewportClick(viewer, ui, float(num(0)), float(num(1)));
        return true;
    }
    if (c.name == "pick") return viewer.pick(float(num(0)), float(num(1))).has_value();
    if (c.name == "focus") return viewer.focusAt(float(num(0)), float(num(1))).has_value();
    if (c.name == "focus-mode") {
        ui.focusOnClick = a[0] == "on";
        return true;
    }
    if (c.name == "bvh-depth") {
        viewer.overlays.bvhDepth = std::max(0, int(num(0)));
        return true;
    }
    if (c.name == "heat-scale") {
        viewer.heatScaleAuto = a[0] == "auto";
        if (!viewer.heatScaleAuto) viewer.heatScale = float(num(0));
        viewer.redisplay();
        return true;
    }
    if (c.name == "select") {
        const int i = int(num(0));
        if (i < -1 || i >= objectCount(viewer.scene())) return false;
        viewer.selection.select(i);
        return true;
    }
    if (c.name == "select-light") {
        const int i = int(num(0));
        if (i < -1 || i >= int(viewer.scene().lights.size())) return false;
        viewer.selection.selectLight(i);
        return true;
    }
    if (c.name == "debug-view") {
        viewer.setDebugView(*parseDebugView(a[0]));
        return true;
    }
    if (c.name == "debug-bounce") {
        viewer.setDebugBounce(int(num(0)));
        return true;
    }
    if (c.name == "overlay") {
        OverlaySettings& o = viewer.overlays;
        if (a[0] == "paths") viewer.inspection.overlay.show = a[1] == "on";
        else if (a[0] == "lights") o.lights = a[1] == "on";
        else (a[0] == "boxes" ? o.boxes : a[0] == "selected" ? o.selectedOnly : a[0] == "bvh" ? o.bvh : o.meshBvh) = a[1] == "on";
        return true;
    }
    if (c.name == "inspect") {
        // X Y are pixels of the scene's image (render.width × height), so lessons work at any
        // resolution scale: mapped onto the traced image here.
        if (a.size() > 2) viewer.inspection.pathCount = int(num(2));
        const Scene& s = viewer.scene();
        const double sx = double(viewer.imageWidth()) / double(std::max(1, s.render.width));
        const double sy = double(viewer.imageHeight()) / double(std::max(1, s.render.height));
        return viewer.inspection.inspect(viewer, int(num(0) * sx), int(num(1) * sy));
    }
    if (c.name == "inspect-export") return viewer.inspection.exportPaths(viewer, a[0]);
    if (c.name == "explore") {
        const auto& paths = viewer.inspection.paths();
        const std::size_t path = a.size() > 1 ? std::size_t(num(1)) : 0, bounce = std::size_t(num(0));
        if (path >= paths.size() || bounce >= paths[path].bounces.size() || !paths[path].bounces[bounce].hit) {
            viewer.log().error("explore: no surface bounce " + a[0] + " on an inspected path (inspect a pixel first)");
            return false;
        }
        viewer.brdfExplorer.fromBounce(paths[path].bounces[bounce]);
        viewer.brdfExplorer.panelOpen = true;
        return true;
    }
    if (c.name == "panel") {
        (a[0] == "inspector" ? viewer.inspection.panelOpen : viewer.brdfExplorer.panelOpen) = a[1] == "on";
        return true;
    }
    if (c.name == "scale") {
        viewer.setResolutionScale(float(num(0)));
        return true;
    }
    if (c.name == "bounce-step") {
        viewer.setBounceStep(a[0] == "off" ? 0 : a[0] == "next" ? viewer.bounceStep() + 1 : int(num(0)));
        return true;
    }
    if (c.name == "stage") return viewer.document().set("render.stage", a[0]);
    if (c.name == "expect") {
        const ViewState view{std::string(debugViewName(viewer.debugView())), viewer.resolutionScale(), viewer.bounceStep()};
        const std::string failure = expectationFailure(viewer.scene(), view, a[0], a[1]);
        if (!failure.empty()) viewer.log().error("expect: " + failure);
        return failure.empty();
    }
    if (c.name == "hold") {   // lesson sessions cut steps at it (lesson/lesson.h)
        viewer.log().error("hold: only a lesson step holds (the presenter's key goes on)");
        return false;
    }
    if (c.name == "split") {
        if (a[0] == "off") ui.split.stop();
        else ui.split.start(a[0] == "time" ? SplitBudget::EqualTime : SplitBudget::EqualSamples);
        return true;
    }
    if (c.name == "split-a" || c.name == "split-b") {
        const std::string error = ui.split.addOverride(c.name == "split-a" ? 0 : 1, a[0], a[1], viewer.scene());
        if (!error.empty()) viewer.log().error(c.name + ": " + error);
        return error.empty();
    }
    if (c.name == "split-divider") {
        ui.split.divider = std::clamp(float(num(0)), 0.0f, 1.0f);
        return true;
    }
    if (c.name == "ui-scale") {
        ui.uiScale = std::clamp(float(num(0)), kMinUiScale, kMaxUiScale);
        return true;
    }
    if (c.name == "key") {   // pressed in the window loop, as a presenter's clicker would
        ui.pendingKey = a[0];
        ui.pendingKeyFrames = a.size() > 1 ? int(num(1)) : 1;
        waitFrames_ = ui.pendingKeyFrames + 1;   // held, then released

        return true;
    }
    if (c.name == "lesson") {
        if (const auto error = ui.lesson.open(a[0])) {
            viewer.log().error(*error);
            return false;
        }
        ui.showTeach = true;
        ui.teachTab = 0;
        viewer.log().info("lesson " + ui.lesson.lesson().title);
        return true;
    }
    if (c.name == "lesson-step") return ui.lesson.apply(int(num(0)) - 1);
    if (c.name == "teach") {
        ui.showTeach = a[0] != "off";
        ui.teachTab = a[0] == "lesson" ? 0 : a[0] == "classroom" ? 1 : a[0] == "self-test" ? 2 : -1;
        return true;
    }
    if (c.name == "self-test") {
        ui.selfTest = runSelfTest();
        for (const SelfTestResult& r : ui.selfTest.results) viewer.log().info("self-test: " + describe(r));
        viewer.log().info("self-test: " + std::string(ui.selfTest.pass() ? "all pass" : "FAILED") + " in " +
                          std::to_string(ui.selfTest.seconds) + " s on " + ui.selfTest.driver);
        return ui.selfTest.pass();
    }
    if (c.name == "pause") viewer.setPaused(true);
    else if (c.name == "resume") viewer.setPaused(false);
    else if (c.name == "reset") viewer.resetAccumulation();
    else if (c.name == "wait-spp") waitSpp_ = std::min((long long)num(0), maxWaitSpp_);
    else if (c.name == "wait-frames") waitFrames_ = int(num(0));
    else if (c.name == "screenshot") ui.pendingScreenshot = a[0];
    else if (c.name == "export") return ui.split.on() ? ui.split.exportComposite(a[0], viewer) : viewer.exportRender(a[0]);
    else if (c.name == "save") return viewer.document().save(a[0]);
    else if (c.name == "window") host.resizeWindow(int(num(0)), int(num(1)));
    else if (c.name == "drop") host.dropFile(a[0]);   // opened by the window loop next frame
    return true;
}

} // namespace raylab::ui
