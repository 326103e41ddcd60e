#pragma once
// The viewer's key actions, one row each: the name the script's `key` command presses, the key
// and whether Ctrl goes with it, and the label buttons and tooltips show; then the camera keys.
// The window's key handling, the panels' buttons and the script all read these tables;
// ui/app/actions.cpp binds each action to what it does. Key codes are GLFW's (glfw3.h; checked
// there), as ImGui's GLFW backend indexes its keys by them.
#include <array>
#include <string_view>

namespace raylab {

enum class KeyAction {
    NextStep, PreviousStep, Pause, Reset, ReloadShaders, Export, Screenshot,
    ToggleTeach, SaveScene, UiScaleUp, UiScaleDown, UiScaleReset, TogglePresenter,
};

namespace keycode {   // GLFW_KEY_*
inline constexpr int kNone = -1, kSpace = 32, kMinus = 45, k0 = 48, kEqual = 61, kA = 65, kD = 68, kE = 69, kQ = 81,
                     kR = 82, kS = 83, kW = 87, kRight = 262, kLeft = 263, kDown = 264, kUp = 265, kPageUp = 266,
                     kPageDown = 267, kF1 = 290, kF2 = 291, kF5 = 294, kF9 = 298, kF12 = 301, kKpSubtract = 333, kKpAdd = 334,
                     kLeftControl = 341;
} // namespace keycode

enum class Ctrl { Any, Without, With };

struct KeyBinding {
    KeyAction action;
    std::string_view name;       // the script's `key NAME`
    int key;                     // GLFW key code
    int altKey;                  // a second key doing the same (the keypad's), or keycode::kNone
    Ctrl ctrl;
    std::string_view keyLabel;   // the key as buttons show it: "F5", "Ctrl+S"
    std::string_view label;      // what it does
};

inline constexpr std::array<KeyBinding, 13> kKeyBindings = {{
    {KeyAction::NextStep, "page-down", keycode::kPageDown, keycode::kNone, Ctrl::Any, "PgDn", "next lesson step"},
    {KeyAction::PreviousStep, "page-up", keycode::kPageUp, keycode::kNone, Ctrl::Any, "PgUp", "previous lesson step"},
    {KeyAction::Pause, "space", keycode::kSpace, keycode::kNone, Ctrl::Any, "Space", "pause / resume"},
    {KeyAction::Reset, "r", keycode::kR, keycode::kNone, Ctrl::Without, "R", "restart accumulation"},
    {KeyAction::ReloadShaders, "f5", keycode::kF5, keycode::kNone, Ctrl::Any, "F5", "reload shaders"},
    {KeyAction::Export, "f9", keycode::kF9, keycode::kNone, Ctrl::Any, "F9", "export the render"},
    {KeyAction::Screenshot, "f12", keycode::kF12, keycode::kNone, Ctrl::Any, "F12", "screenshot of the window"},
    {KeyAction::ToggleTeach, "f1", keycode::kF1, keycode::kNone, Ctrl::Any, "F1", "show / hide the Teach window"},
    {KeyAction::TogglePresenter, "f2", keycode::kF2, keycode::kNone, Ctrl::Any, "F2", "show / hide the presenter view"},
    {KeyAction::SaveScene, "ctrl+s", keycode::kS, keycode::kNone, Ctrl::With, "Ctrl+S", "save the scene"},
    {KeyAction::UiScaleUp, "ctrl+=", keycode::kEqual, keycode::kKpAdd, Ctrl::With, "Ctrl+=", "larger UI"},
    {KeyAction::UiScaleDown, "ctrl+-", keycode::kMinus, keycode::kKpSubtract, Ctrl::With, "Ctrl+-", "smaller UI"},
    {KeyAction::UiScaleReset, "ctrl+0", keycode::k0, keycode::kNone, Ctrl::With, "Ctrl+0", "UI scale 1"},
}};

constexpr const KeyBinding& keyBinding(KeyAction action) {
    for (const KeyBinding& b : kKeyBindings)
        if (b.action == action) return b;
    return kKeyBindings[0];
}

// The viewport's camera keys: they act while held (ui/panels/viewport_panel.cpp), not on a press.
enum class CameraMotion { Forward, Back, Left, Right, Down, Up, TurnLeft, TurnRight, LookUp, LookDown };

struct CameraKey {
    CameraMotion motion;
    std::string_view name;   // the script's `key NAME`
    int key;                 // GLFW key code
};

inline constexpr std::array<CameraKey, 10> kCameraKeys = {{
    {CameraMotion::Forward, "w", keycode::kW},        {CameraMotion::Back, "s", keycode::kS},
    {CameraMotion::Left, "a", keycode::kA},           {CameraMotion::Right, "d", keycode::kD},
    {CameraMotion::Down, "q", keycode::kQ},           {CameraMotion::Up, "e", keycode::kE},
    {CameraMotion::TurnLeft, "left", keycode::kLeft}, {CameraMotion::TurnRight, "right", keycode::kRight},
    {CameraMotion::LookUp, "up", keycode::kUp},       {CameraMotion::LookDown, "down", keycode::kDown},
}};

constexpr int cameraKey(CameraMotion motion) {
    for (const CameraKey& k : kCameraKeys)
        if (k.motion == motion) return k.key;
    return keycode::kNone;
}

} // namespace raylab
