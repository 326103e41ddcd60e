// The presenter view: the lesson's position, the next step, the clock and the teacher's notes with
// the answers, for the teacher's screen (app/presenter.h). Drawn into the current ImGui window: a
// window of its own (--presenter-window) or the main window's Presenter panel (F2).
#include "panels/markdown_view.h"
#include "panels/panels.h"

#include <imgui.h>

namespace raylab::ui {

void drawPresenterPanel(UiState& ui) {
    const PresenterContent c = ui.presenter.content(ui.lesson, ImGui::GetTime());
    if (lessonFont()) ImGui::PushFont(lessonFont());
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", c.title.c_str());
    if (!c.level.empty()) ImGui::TextDisabled("%s", c.level.c_str());
    ImGui::Text("%s", c.step.c_str());
    ImGui::TextDisabled("%s", c.next.c_str());
    ImGui::Text("%s", c.clock.c_str());
    ImGui::PopTextWrapPos();
    if (ui.lesson.isOpen()) {
        ImGui::Separator();
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", c.questionsHeading.c_str());
        for (std::size_t i = 0; i < c.questions.size(); ++i) {
            ImGui::PushID(int(i));
            drawMarkdown(std::to_string(i + 1) + ". " + c.questions[i]);
            ImGui::PopID();
        }
        ImGui::Separator();
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", c.notesHeading.c_str());
        ImGui::PushID("notes");
        drawMarkdown(c.notes);
        ImGui::PopID();
    }
    if (lessonFont()) ImGui::PopFont();
}

} // namespace raylab::ui
