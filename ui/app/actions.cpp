#include "app/actions.h"

namespace raylab::ui {

void runAction(KeyAction action, Viewer& viewer, UiState& ui) {
    switch (action) {
    case KeyAction::NextStep: ui.lesson.next(); return;
    case KeyAction::PreviousStep: ui.lesson.previous(); return;
    case KeyAction::Pause: viewer.setPaused(!viewer.paused()); return;
    case KeyAction::Reset: viewer.resetAccumulation(); return;
    case KeyAction::ReloadShaders:
        if (viewer.reloadShaders()) viewer.log().info("reloaded the shaders (F5)");
        if (ui.exercise.exercise() && ui.exercise.checkOnReload) {
            ui.exercise.check();
            viewer.resetAccumulation();   // the checks used the GPU: start the image over cleanly
        }
        return;
    case KeyAction::Export: viewer.exportRender(ui.exportPath); return;
    case KeyAction::Screenshot: ui.pendingScreenshot = ui.screenshotPath; return;
    case KeyAction::ToggleTeach: ui.showTeach = !ui.showTeach; return;
    case KeyAction::TogglePresenter: ui.presenter.show = !ui.presenter.show; return;
    case KeyAction::SaveScene:
        if (!ui.savePath.empty()) viewer.document().save(ui.savePath);
        return;
    case KeyAction::UiScaleUp: ui.uiScale += 0.25f; return;
    case KeyAction::UiScaleDown: ui.uiScale -= 0.25f; return;
    case KeyAction::UiScaleReset: ui.uiScale = 1.0f; return;
    }
}

std::string buttonLabel(std::string_view text, KeyAction action) {
    return std::string(text) + " (" + std::string(keyBinding(action).keyLabel) + ")";
}

} // namespace raylab::ui
