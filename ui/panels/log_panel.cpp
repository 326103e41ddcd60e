// Log panel: messages and errors, most recent first.
#include "panels/panels.h"

#include <imgui.h>

namespace raylab::ui {

void drawLogPanel(Viewer& viewer, UiState&) {
    if (!ImGui::Begin("Log")) {
        ImGui::End();
        return;
    }
    if (ImGui::Button("Clear")) viewer.log().clear();
    ImGui::BeginChild("##entries");
    for (const LogEntry& e : viewer.log().entries()) {
        const bool err = e.level == LogEntry::Level::Error;
        if (err) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.35f, 1.0f));
        ImGui::TextWrapped("%7.2f  %s", e.time, e.text.c_str());
        if (err) ImGui::PopStyleColor();
    }
    ImGui::EndChild();
    ImGui::End();
}

} // namespace raylab::ui
