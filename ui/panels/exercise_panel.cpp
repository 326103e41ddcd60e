// The Exercise tab of the Teach window: pick a code-track exercise, and the tracer runs with the
// pupil's function (F5 recompiles it after an edit); a compile error shows here at the pupil's
// lines while the previous tracer keeps running; "Check" (and F5) runs its checks and shows the
// verdicts, and a failed render check opens the path inspector at the pixel it picked.
#include "panels/panels.h"

#include <imgui.h>

#include <string>

namespace raylab::ui {
namespace {

const ImVec4 kPass(0.3f, 0.9f, 0.3f, 1.0f);
const ImVec4 kFail(1.0f, 0.35f, 0.3f, 1.0f);

} // namespace

void drawExercisePanel(Viewer& viewer, UiState& ui) {
    ExerciseSession& s = ui.exercise;
    if (s.exercises().empty()) {
        try {
            s.load(exerciseDirectory());
        } catch (const std::exception& e) {
            ImGui::TextWrapped("%s", e.what());
            return;
        }
    }
    const Exercise* current = s.exercise();
    if (ImGui::BeginCombo("exercise", current ? current->name.c_str() : "none (the reference)")) {
        if (ImGui::Selectable("none (the reference)", current == nullptr)) s.select(viewer, -1);
        for (int i = 0; i < int(s.exercises().size()); ++i) {
            const Exercise& e = s.exercises()[std::size_t(i)];
            if (ImGui::Selectable(e.name.c_str(), i == s.selected())) s.select(viewer, i);
        }
        ImGui::EndCombo();
    }
    current = s.exercise();
    if (!current) {
        ImGui::TextWrapped("Pick an exercise: the tracer then runs with the pupil's function in place of its own.");
        return;
    }
    ImGui::TextWrapped("%s, about %d minutes", current->level.c_str(), current->minutes);
    ImGui::TextWrapped("file: %s", s.pupilFile().string().c_str());
    ImGui::TextDisabled("edit it in any editor, then press F5");
    if (!viewer.document().lastError().empty()) {
        ImGui::TextColored(kFail, "does not compile (the previous tracer keeps running):");
        ImGui::TextWrapped("%s", viewer.document().lastError().c_str());
    }
    if (ImGui::Button("Check")) {
        s.check();
        viewer.resetAccumulation();   // the checks used the GPU: start the image over cleanly
    }
    ImGui::SameLine();
    ImGui::Checkbox("check on F5", &s.checkOnReload);
    if (ImGui::Button("Split: yours | the reference")) s.splitWithReference(viewer, ui.split);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Left of the divider your function, right the reference, at equal samples (Classroom tab: split)");
    if (!s.report()) return;
    const ExerciseReport& r = *s.report();
    if (!r.compiled) {
        ImGui::TextColored(kFail, "compile error");
        ImGui::TextWrapped("%s", r.compileError.c_str());
        return;
    }
    ImGui::TextColored(r.pass() ? kPass : kFail, "%s", r.pass() ? "ALL PASS" : "FAILED");
    for (const CheckResult& c : r.checks) {
        ImGui::TextColored(c.pass ? kPass : kFail, "%s", c.pass ? "pass" : "FAIL");
        ImGui::SameLine();
        ImGui::TextWrapped("%s", c.check.c_str());
        ImGui::Indent();
        ImGui::TextWrapped("%s", c.numbers.c_str());
        if (!c.message.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, kFail);
            ImGui::TextWrapped("%s", c.message.c_str());
            ImGui::PopStyleColor();
        }
        if (c.pixelX >= 0) {
            const std::string label = "Inspect pixel (" + std::to_string(c.pixelX) + ", " + std::to_string(c.pixelY) +
                                      ") of the check's scene##" + c.check;
            if (ImGui::Button(label.c_str())) s.inspectDifference(viewer, c);
        }
        ImGui::Unindent();
    }
}

} // namespace raylab::ui
