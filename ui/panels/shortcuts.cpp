// The window's key shortcuts: every row of script/key_actions.h, pressed through ImGui's keys (the
// script's `key` presses the same keys in the window loop).
#include "panels/panels.h"

#include "app/actions.h"

#include <imgui.h>

namespace raylab::ui {
namespace {

bool pressed(int key) { return key >= 0 && ImGui::IsKeyPressed(key, false); }

// The lesson keys act only on an open lesson; in the Teach window Space is its next step.
bool applies(KeyAction action, const UiState& ui) {
    switch (action) {
    case KeyAction::NextStep:
    case KeyAction::PreviousStep: return ui.lesson.isOpen();
    case KeyAction::Pause: return !(ui.teachFocused && ui.lesson.isOpen());
    default: return true;
    }
}

} // namespace

void shortcutKeys(Viewer& viewer, UiState& ui) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return;
    for (const KeyBinding& b : kKeyBindings) {
        if (b.ctrl == Ctrl::With && !io.KeyCtrl) continue;
        if (b.ctrl == Ctrl::Without && io.KeyCtrl) continue;
        if ((pressed(b.key) || pressed(b.altKey)) && applies(b.action, ui)) runAction(b.action, viewer, ui);
    }
}

} // namespace raylab::ui
