#pragma once
// What each key action of script/key_actions.h does to the viewer and the UI state; the window's
// keys (panels/shortcuts.cpp), the panels' buttons and the script's `key` all end here.
#include "app/ui_state.h"
#include "app/viewer.h"
#include "script/key_actions.h"

#include <string>

namespace raylab::ui {

void runAction(KeyAction action, Viewer& viewer, UiState& ui);
// A button's text for the action: "Export (F9)".
std::string buttonLabel(std::string_view text, KeyAction action);

} // namespace raylab::ui
