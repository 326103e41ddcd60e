// The Teach window (F1): tabs for the lesson, classroom mode, the self-test and the code track's
// exercise. Hidden until asked
// for (F1, --lesson, the Render panel's button), so the default layout stays as it was.
#include "panels/panels.h"

#include <imgui.h>

namespace raylab::ui {

void drawTeachWindow(Viewer& viewer, UiState& ui, float windowHeight) {
    ui.teachFocused = false;
    if (!ui.showTeach) return;
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(330.0f, windowHeight), ImGuiCond_FirstUseEver);   // over the left column
    if (ui.teachTab >= 0) ImGui::SetNextWindowFocus();
    if (!ImGui::Begin("Teach", &ui.showTeach)) {
        ImGui::End();
        return;
    }
    ui.teachFocused = ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows);
    if (ImGui::BeginTabBar("##teach")) {
        const char* const names[] = {"Lesson", "Classroom", "Self-test", "Exercise"};
        for (int i = 0; i < 4; ++i) {
            const ImGuiTabItemFlags flags = ui.teachTab == i ? ImGuiTabItemFlags_SetSelected : 0;
            if (ImGui::BeginTabItem(names[i], nullptr, flags)) {
                if (i == 0) drawLessonPanel(viewer, ui);
                else if (i == 1) drawClassroomPanel(viewer, ui);
                else if (i == 2) drawSelfTestPanel(viewer, ui);
                else drawExercisePanel(viewer, ui);
                ImGui::EndTabItem();
            }
        }
        ui.teachTab = -1;
        ImGui::EndTabBar();
    }
    ImGui::End();
}

} // namespace raylab::ui
