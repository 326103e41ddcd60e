// Classroom UI scale: fonts (io.FontGlobalScale) and sizes (style.ScaleAllSizes of the style as it
// was first seen), remembered in imgui.ini as "[Raylab][Classroom] UiScale=S".
#include "panels/panels.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdio>

namespace raylab::ui {
namespace {

UiState* g_state = nullptr;   // the settings handler's target (one UI per process)

void* readOpen(ImGuiContext*, ImGuiSettingsHandler*, const char* name) {
    return std::string_view(name) == "Classroom" ? static_cast<void*>(g_state) : nullptr;
}

void readLine(ImGuiContext*, ImGuiSettingsHandler*, void* entry, const char* line) {
    float s = 0.0f;
    if (entry && std::sscanf(line, "UiScale=%f", &s) == 1)
        static_cast<UiState*>(entry)->uiScale = std::clamp(s, kMinUiScale, kMaxUiScale);
}

void writeAll(ImGuiContext*, ImGuiSettingsHandler* handler, ImGuiTextBuffer* out) {
    if (!g_state) return;
    out->appendf("[%s][Classroom]\nUiScale=%.3f\n\n", handler->TypeName, double(g_state->uiScale));
}

} // namespace

void installUiScaleSettings(UiState& ui) {
    g_state = &ui;
    ImGuiSettingsHandler h;
    h.TypeName = "Raylab";
    h.TypeHash = ImHashStr("Raylab");
    h.ReadOpenFn = readOpen;
    h.ReadLineFn = readLine;
    h.WriteAllFn = writeAll;
    ImGui::GetCurrentContext()->SettingsHandlers.push_back(h);
}

void applyUiScale(UiState& ui) {
    static ImGuiStyle base = ImGui::GetStyle();
    static float applied = 1.0f;
    ui.uiScale = std::clamp(ui.uiScale, kMinUiScale, kMaxUiScale);
    if (ui.uiScale == applied) return;
    ImGuiStyle style = base;
    style.ScaleAllSizes(ui.uiScale);
    ImGui::GetStyle() = style;
    ImGui::GetIO().FontGlobalScale = ui.uiScale;
    applied = ui.uiScale;
    ImGui::MarkIniSettingsDirty();
}

} // namespace raylab::ui
