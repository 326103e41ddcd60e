#pragma once
// The viewer's window loop: each frame takes the window's events, runs the scripts, traces for
// the time the frame pacer allows (or waits while idle), draws the workspace and swaps.
#include "app/frame_pacer.h"
#include "app/log.h"
#include "app/script_runner.h"
#include "app/ui_state.h"
#include "app/viewer.h"
#include "app_cli.h"
#include "frame_times.h"
#include "window_io.h"

#include <memory>
#include <optional>

struct GLFWwindow;

namespace raylab::ui {

class PresenterWindow;

class ViewerLoop {
public:
    // Needs ImGui set up on `window` (imgui_setup.h) and `events` installed on it.
    ViewerLoop(GLFWwindow* window, WindowEvents& events, AppOptions& options, Log& log);
    // Until the window closes, the script ends or --frames are done; returns the exit status.
    int run();
    ~ViewerLoop();

private:
    void openFirstScene();
    void openExercise();   // --exercise: the tracer with the pupil's function, the Exercise tab open
    bool runScripts(int frame);      // false once the automation script has ended
    double waitWhileIdle(int frame); // the seconds spent waiting for input or a new image
    double drawFrame();              // the UI draw's milliseconds
    void printReport() const;
    void drawPresenterWindow();      // --presenter-window: opens, draws or closes it as ui.presenter.show says

    GLFWwindow* window_;
    WindowEvents& events_;
    AppOptions& options_;
    Log& log_;
    Viewer viewer_;
    UiState ui_;
    WindowHost host_;
    ScriptKeys scriptKeys_;
    std::optional<ScriptRunner> stepScript_;   // the lesson step being applied
    FramePacer pacer_;
    FrameTimes times_;
    std::unique_ptr<PresenterWindow> presenter_;
    int exitCode_ = 0;
};

} // namespace raylab::ui
