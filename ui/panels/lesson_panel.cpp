// The Lesson tab of the Teach window: a picker over lessons/, the open lesson's Markdown, a button
// per step that runs its script (the window loop runs it, app/lesson_session.h), the current step
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

void heading(const char* text) {
    ImGui::Spacing();
    ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", text);
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

void picker(Viewer& viewer, UiState& ui) {
    static bool scanned = false;
    if (!scanned) {
        ui.lesson.scan(defaultLessonDirectory(shaderDirectory()));
        scanned = true;
    }
    const std::string current = ui.lesson.isOpen() ? ui.lesson.lesson().title : "Choose a lesson";
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##lesson", current.c_str())) {
        for (const LessonEntry& e : ui.lesson.entries()) {
            const std::string label = e.error.empty() ? e.title : e.file.filename().string() + " (does not load)";
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
        ImGui::TextWrapped("Lessons are Markdown files in lessons/ (raylab --lesson FILE opens one). Each step has a "
                           "button that sets the viewer's state; PageDown / PageUp move through the steps.");
        return;
    }
    const Lesson& l = ui.lesson.lesson();
    const int n = ui.lesson.stepCount(), cur = ui.lesson.current();
    if (ImGui::Button(("< " + buttonLabel("Previous", KeyAction::PreviousStep)).c_str())) runAction(KeyAction::PreviousStep, viewer, ui);
    ImGui::SameLine();
    if (ImGui::Button((buttonLabel("Next", KeyAction::NextStep) + " >").c_str())) runAction(KeyAction::NextStep, viewer, ui);
    ImGui::SameLine();
    ImGui::Text("step %d of %d", cur + 1, n);
    if (cur >= 0 && ui.lesson.partCount(cur) > 1) {
        ImGui::SameLine();
        ImGui::Text("(part %d of %d: Next holds the next state)", ui.lesson.currentPart() + 1, ui.lesson.partCount(cur));
    }
    ImGui::Separator();
    ImGui::BeginChild("##lesson-text");
    if (lessonFont()) ImGui::PushFont(lessonFont());
    static int scrolledTo = -2;
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", l.title.c_str());
    ImGui::PopTextWrapPos();
    ImGui::TextDisabled("Scene: %s", l.scene.c_str());
    if (!l.level.empty() || l.minutes > 0)
        ImGui::TextDisabled("Level: %s, %d minutes", l.level.empty() ? "-" : l.level.c_str(), l.minutes);
    ImGui::PushID("intro");
    drawMarkdown(l.introduction, &l);
    ImGui::PopID();
    heading("Learning goals");
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
        const std::string label = "Step " + std::to_string(i + 1) + ": " + step.title + (step.optional ? " (optional)" : "");
        if (ImGui::Button(label.c_str())) ui.lesson.apply(i);
        if (active) ImGui::PopStyleColor(2);
        if (ImGui::IsItemHovered()) {
            std::string script;
            for (const ScriptCommand& c : step.commands) script += c.text().substr(c.text().find(": ") + 2) + "\n";
            ImGui::SetTooltip("Sets the viewer's state:\n%s", script.c_str());
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
    heading("Questions");
    ImGui::PushID("questions");
    listItems(l.questions, true, l);
    ImGui::PopID();
    heading("Exercise");
    ImGui::PushID("exercise");
    drawMarkdown(l.exercise, &l);
    ImGui::PopID();
    if (!l.writeItYourself.empty()) {
        heading("Write it yourself");
        ImGui::PushID("code");
        drawMarkdown(l.writeItYourself, &l);
        // Each exercise the section names opens in the Exercise tab, the tracer running the pupil's file.
        for (const std::string& name : l.codeExercises) {
            if (!ImGui::Button(("Open exercise " + name).c_str())) continue;
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
        heading("Going further");
        ImGui::PushID("further");
        drawMarkdown(l.goingFurther, &l);
        ImGui::PopID();
    }
    // Class mode: the answers stay off the projector, on the presenter view.
    if (!l.teacherNotes.empty() && ui.presenter.classMode) {
        ImGui::Spacing();
        ImGui::TextDisabled("Teacher's notes: on the presenter view (%s)", std::string(keyBinding(KeyAction::TogglePresenter).keyLabel).c_str());
    } else if (!l.teacherNotes.empty() && ImGui::CollapsingHeader("Teacher's notes")) {
        ImGui::PushID("notes");
        drawMarkdown(l.teacherNotes, &l);
        ImGui::PopID();
    }
    if (!l.sources.empty() && ImGui::CollapsingHeader("Sources")) {
        ImGui::PushID("sources");
        drawMarkdown(l.sources, &l);
        ImGui::PopID();
    }
    if (lessonFont()) ImGui::PopFont();
    ImGui::EndChild();
}

} // namespace raylab::ui
