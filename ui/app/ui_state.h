#pragma once
// What the views share besides the Viewer model: text boxes, requests that the window loop carries
// out (a screenshot needs the finished frame), and where the viewport drew the image last frame.
#include "app/exercise_session.h"
#include "app/lesson_session.h"
#include "app/presenter.h"
#include "app/split_screen.h"
#include "inspect/sample_points.h"
#include "selftest/self_test.h"

#include <cstdint>
#include <string>

namespace raylab::ui {

inline constexpr float kMinUiScale = 0.5f;   // ui-scale range (projectors: 1.5 to 2.5)
inline constexpr float kMaxUiScale = 4.0f;

struct ImageRect {
    float x = 0.0f;   // window pixels, top-left of the shown image
    float y = 0.0f;
    float width = 0.0f;
    float height = 0.0f;
    bool valid() const { return width > 0.0f && height > 0.0f; }
};

struct UiState {
    std::string openPath;          // the path box of the Render panel
    std::string savePath;          // where "Save scene" writes
    std::string screenshotPath = "raylab-screenshot.png";
    std::string exportPath = "raylab-render.exr";
    std::string pendingScreenshot; // set by a button, key or script; done after the frame is drawn
    bool pixelTooltip = true;      // value under the cursor
    bool focusOnClick = false;     // click-to-focus armed (Camera panel): the next click focuses
    ImageRect image;               // where the viewport drew the traced image
    bool dragging = false;         // a mouse drag in the viewport is moving the camera

    // Teaching and classroom mode (the Teach window: Lesson, Classroom and Self-test tabs).
    bool showTeach = false;        // the Teach window is open (F1, --lesson, the script's lesson)
    int teachTab = -1;             // a tab to bring to the front next frame (0 lesson, 1 classroom, 2 self-test, 3 exercise)
    std::string pendingKey;        // a key the script presses next frame ("page-down", "page-up")
    int pendingKeyFrames = 1;      // how many frames the script holds it down
    bool focusViewport = false;    // the viewport takes the keyboard next frame (the script's camera keys)
    bool teachFocused = false;     // the Teach window had the keyboard last frame (arrows and Space step)
    LessonSession lesson;          // the Lesson panel's model; its step scripts run in the window loop
    PresenterState presenter;      // class mode and the presenter view (app/presenter.h)
    ExerciseSession exercise;      // the Exercise tab's model: the code track's pupil function in the tracer
    bool stepScriptRunning = false;   // a lesson step's script is running (an automation script waits)
    SplitScreen split;             // A/B split screen
    bool draggingDivider = false;  // the mouse is dragging the split screen's divider
    float uiScale = 1.0f;          // fonts and sizes, for projectors (Ctrl +/-/0; remembered in imgui.ini)
    stats::ConvergenceSeries convergence;   // the viewer's beauty image (app/convergence_watch.h)
    std::uint64_t convergenceRun = ~std::uint64_t(0);   // the viewer's restart count it belongs to
    SelfTestReport selfTest;       // the last self-test (empty before the first run)
    bool selfTestRequested = false;   // run it at the start of the next frame
    SamplePointsQuery samplePoints;   // the Render panel's sample-points plot (pair, bounce, count)
};

} // namespace raylab::ui
