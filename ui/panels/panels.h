#pragma once
// The viewer's views, one file each: ImGui windows that read and change the Viewer model. They
// hold no state of their own besides UiState, so the same calls run in a window and in the null
// ImGui frames of the tests.
#include "app/ui_state.h"
#include "app/viewport_click.h"
#include "app/viewer.h"

namespace raylab::ui {

void drawViewport(Viewer& viewer, UiState& ui);       // viewport_panel.cpp: image, overlays, mouse, keys
void drawRenderPanel(Viewer& viewer, UiState& ui);    // render_panel.cpp: files, passes, stop conditions
void drawCameraPanel(Viewer& viewer, UiState& ui);    // camera_panel.cpp
void drawMaterialPanel(Viewer& viewer, UiState& ui);  // material_panel.cpp: outliner, object, material
// The selected light's keys (light_panel.cpp), drawn by the Material panel when the outliner's
// selection is a light; positions drag by positionSpeed per pixel.
void drawLightKeys(Viewer& viewer, float positionSpeed);
void drawOverlaysPanel(Viewer& viewer, UiState& ui);  // overlays_panel.cpp
void drawDebugPanel(Viewer& viewer, UiState& ui);     // debug_panel.cpp
void drawStatsPanel(Viewer& viewer, UiState& ui);     // stats_panel.cpp
void drawLogPanel(Viewer& viewer, UiState& ui);       // log_panel.cpp
void drawInspectorPanel(Viewer& viewer, UiState& ui);     // inspector_panel.cpp: pixel path inspector
void drawBrdfExplorerPanel(Viewer& viewer, UiState& ui);  // brdf_explorer_panel.cpp
// The inspected paths over the image (inspector_panel.cpp), called by the viewport.
void drawPathOverlay(Viewer& viewer, const ImageRect& image);

// Teaching: the Teach window (teach_panel.cpp) with the Lesson (lesson_panel.cpp),
// Classroom (classroom_panel.cpp), Self-test (self_test_panel.cpp) and Exercise tabs.
void drawTeachWindow(Viewer& viewer, UiState& ui, float windowHeight);
void drawLessonPanel(Viewer& viewer, UiState& ui);
void drawClassroomPanel(Viewer& viewer, UiState& ui);
void drawSelfTestPanel(Viewer& viewer, UiState& ui);
void drawExercisePanel(Viewer& viewer, UiState& ui);   // exercise_panel.cpp: the code track
// The presenter view (presenter_panel.cpp) into the current window: the main window's Presenter
// panel (F2) or the presenter's own window (ui/presenter_window.h).
void drawPresenterPanel(UiState& ui);
// The Teach window's presenter keys (lesson_panel.cpp): Right/Left/Space while it has the
// keyboard. Call between NewFrame and drawing.
void presenterKeys(UiState& ui);
// The key actions of script/key_actions.h (shortcuts.cpp). Call between NewFrame and drawing,
// before applyUiScale.
void shortcutKeys(Viewer& viewer, UiState& ui);
// The A/B split screen over the image (split_view.cpp); the viewport calls it after the image.
void drawSplitView(UiState& ui, const ImageRect& image);
// UI scale (ui_scale.cpp): register the imgui.ini entry before the first frame; apply once a frame
// before NewFrame (Ctrl + = / - / 0 change it).
void installUiScaleSettings(UiState& ui);
void applyUiScale(UiState& ui);

// All of the above, laid out for a window of the given size on first use (workspace.cpp; imgui.ini
// keeps what the user changes afterwards).
void drawWorkspace(Viewer& viewer, UiState& ui, float windowWidth, float windowHeight);

} // namespace raylab::ui
