// The Lesson tab of the Teach window: the edition's language (English, Nederlands), a picker over
// its lessons (lessons/, lessons/nl/), the open lesson's Markdown, a button per step that runs its script (the window loop runs it, app/lesson_session.h), the current step
// highlighted, and the presenter keys of this window (arrows and Space while it has the keyboard;
// PageDown/PageUp are key actions, script/key_actions.h).
#include "panels/markdown_view.h"
#include "panels/panels.h"

#include "app/actions.h"

#include "gl/shader_source.h"

#include <imgui.h>

#include <string>

namespace raylab::ui {
namespace {

void heading(const std::string& text) {
    ImGui::Spacing();
    ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", text.c_str());
    ImGui::Separator();
}

void listItems(const std::vector<std::string>& items, bool numbered, const Lesson& lesson) {
    for (std::size_t i = 0; i < items.size(); ++i) {
        ImGui::PushID(int(i));
        const std::string md = (numbered ? std::to_string(i + 1) + ". " : "- ") + items[i];
        drawMarkdown(md, &lesson);
        ImGui::PopID();
    }
}

// The edition's language; switching keeps the open lesson's step (app/lesson_session.h).
void languageChoice(Viewer& viewer, UiState& ui) {
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("Nederlands").x + ImGui::GetFrameHeight() * 2.0f);
    if (!ImGui::BeginCombo("##language", lessonWords(ui.lesson.language()).languageName)) return;
    for (const char* language : kLessonLanguages) {
        if (!ImGui::Selectable(lessonWords(language).languageName, ui.lesson.language() == language)) continue;
        if (const auto error = ui.lesson.setLanguage(language)) viewer.log().error(*error);
    }
    ImGui::EndCombo();
}

void picker(Viewer& viewer, UiState& ui) {
    static bool scanned = false;
    if (!scanned) {
        ui.lesson.scan(defaultLessonDirectory(shaderDirectory()));
        scanned = true;
    }
    const LessonWords& w = lessonWords(ui.lesson.language());
    languageChoice(viewer, ui);
    ImGui::SameLine();
    const std::string current = ui.lesson.isOpen() ? ui.lesson.lesson().title : w.chooseLesson;
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##lesson", current.c_str())) {
        for (const LessonEntry& e : ui.lesson.entries()) {
            const std::string label = e.error.empty() ? e.title : e.file.filename().string() + " (" + w.doesNotLoad + ")";
            const bool selected = ui.lesson.isOpen() && ui.lesson.lesson().file == e.file;
            if (ImGui::Selectable(label.c_str(), selected)) {
                if (const auto error = ui.lesson.open(e.file)) viewer.log().error(*error);
                else viewer.log().info("lesson " + ui.lesson.lesson().title);
            }
            if (!e.error.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.error.c_str());
        }
        ImGui::EndCombo();
    }
}

} // namespace

void presenterKeys(UiState& ui) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || !ui.lesson.isOpen()) return;
    if (!ui.teachFocused) return;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow), false) ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false))
        ui.lesson.next();
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow), false)) ui.lesson.previous();
}

void drawLessonPanel(Viewer& viewer, UiState& ui) {
    picker(viewer, ui);
    if (!ui.lesson.isOpen()) {
        ImGui::TextWrapped("%s", lessonWords(ui.lesson.language()).panelHelp);
        return;
    }
    const Lesson& l = ui.lesson.lesson();
    const LessonWords& w = lessonWords(l.language);
    const int n = ui.lesson.stepCount(), cur = ui.lesson.current();
    if (ImGui::Button(("< " + buttonLabel(w.previous, KeyAction::PreviousStep) + "###previous").c_str()))
        runAction(KeyAction::PreviousStep, viewer, ui);
    ImGui::SameLine();
    if (ImGui::Button((buttonLabel(w.next, KeyAction::NextStep) + " >###next").c_str())) runAction(KeyAction::NextStep, viewer, ui);
    ImGui::SameLine();
    ImGui::Text("%s %d %s %d", w.stepInText, cur + 1, w.of, n);
    if (cur >= 0 && ui.lesson.partCount(cur) > 1) {
        ImGui::SameLine();
        ImGui::Text("(%s %d %s %d: %s)", w.part, ui.lesson.currentPart() + 1, w.of, ui.lesson.partCount(cur), w.nextHolds);
    }
    ImGui::Separator();
    ImGui::BeginChild("##lesson-text");
    if (lessonFont()) ImGui::PushFont(lessonFont());
    static int scrolledTo = -2;
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", l.title.c_str());
    ImGui::PopTextWrapPos();
    ImGui::TextDisabled("%s: %s", w.scene, l.scene.c_str());
    if (!l.level.empty() || l.minutes > 0)
        ImGui::TextDisabled("%s: %s, %d %s", w.level, l.level.empty() ? "-" : l.level.c_str(), l.minutes, w.minutes);
    ImGui::PushID("intro");
    drawMarkdown(l.introduction, &l);
    ImGui::PopID();
    heading(l.heading(LessonRole::Goals));
    ImGui::PushID("goals");
    listItems(l.goals, false, l);
    ImGui::PopID();
    for (int i = 0; i < n; ++i) {
        const LessonStep& step = l.steps[std::size_t(i)];
        ImGui::PushID(i);
        ImGui::Spacing();
        const bool active = i == cur;
        const ImVec2 top = ImGui::GetCursorScreenPos();
        if (active) {
            ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.85f, 0.55f, 0.1f, 1.0f));
            ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(0.95f, 0.65f, 0.2f, 1.0f));
        }
        const std::string label = step.heading + (step.optional ? " (" + std::string(w.optional) + ")" : "") + "###step";
        if (ImGui::Button(label.c_str())) ui.lesson.apply(i);
        if (active) ImGui::PopStyleColor(2);
        if (ImGui::IsItemHovered()) {
            std::string script;
            for (const ScriptCommand& c : step.commands) script += c.text().substr(c.text().find(": ") + 2) + "\n";
            ImGui::SetTooltip("%s\n%s", w.setsState, script.c_str());
        }
        if (active && scrolledTo != cur) {
            ImGui::SetScrollHereY(0.1f);
            scrolledTo = cur;
        }
        drawMarkdown(step.text, &l);
        if (active) {   // a bar down the left edge of the current step
            const ImVec2 bottom = ImGui::GetCursorScreenPos();
            ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(top.x - 6.0f, top.y), ImVec2(top.x - 3.0f, bottom.y),
                                                      IM_COL32(230, 150, 30, 255));
        }
        ImGui::PopID();
    }
    heading(l.heading(LessonRole::Questions));
    ImGui::PushID("questions");
    listItems(l.questions, true, l);
    ImGui::PopID();
    heading(l.heading(LessonRole::Exercise));
    ImGui::PushID("exercise");
    drawMarkdown(l.exercise, &l);
    ImGui::PopID();
    if (!l.writeItYourself.empty()) {
        heading(l.heading(LessonRole::Code));
        ImGui::PushID("code");
        drawMarkdown(l.writeItYourself, &l);
        // Each exercise the section names opens in the Exercise tab, the tracer running the pupil's file.
        for (const std::string& name : l.codeExercises) {
            if (!ImGui::Button((w.openExercise + (" " + name)).c_str())) continue;
            try {
                if (ui.exercise.exercises().empty()) ui.exercise.load(exerciseDirectory());
                const auto& all = ui.exercise.exercises();
                for (int i = 0; i < int(all.size()); ++i)
                    if (all[std::size_t(i)].name == name) ui.exercise.select(viewer, i);
                ui.teachTab = 3;
            } catch (const std::exception& e) {
                viewer.log().error(e.what());
            }
        }
        ImGui::PopID();
    }
    if (!l.goingFurther.empty()) {
        heading(l.heading(LessonRole::Further));
        ImGui::PushID("further");
        drawMarkdown(l.goingFurther, &l);
        ImGui::PopID();
    }
    // Class mode: the answers stay off the projector, on the presenter view.
    if (!l.teacherNotes.empty() && ui.presenter.classMode) {
        ImGui::Spacing();
        ImGui::TextDisabled("%s (%s)", w.notesOnPresenter, std::string(keyBinding(KeyAction::TogglePresenter).keyLabel).c_str());
    } else if (!l.teacherNotes.empty() && ImGui::CollapsingHeader((l.heading(LessonRole::Notes) + "###notes").c_str())) {
        ImGui::PushID("notes");
        drawMarkdown(l.teacherNotes, &l);
        ImGui::PopID();
    }
    if (!l.sources.empty() && ImGui::CollapsingHeader((l.heading(LessonRole::Sources) + "###sources").c_str())) {
        ImGui::PushID("sources");
        drawMarkdown(l.sources, &l);
        ImGui::PopID();
    }
    if (lessonFont()) ImGui::PopFont();
    ImGui::EndChild();
}

} // namespace raylab::ui
