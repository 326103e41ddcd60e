#pragma once
// The presenter view's model: what the teacher sees and the class does not — where the lesson
// stands (step and sub-step, core or optional, the next step), the time against the lesson's
// minutes, and the teacher's notes with the answers. Class mode hides the notes in the Lesson
// panel; the presenter view (its own window, or a panel of the main window toggled by F2) shows
// them. No ImGui, no GL.
#include "app/lesson_session.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::ui {

// The words around the lesson's own are the lesson's language's (lesson/lesson_words.h).
struct PresenterContent {
    std::string title;          // the lesson's title, or "No lesson open"
    std::string level;          // "VWO 5–6, 45 minutes" ("" when the lesson gives neither)
    std::string step;           // "Step 2 of 6: Lambert's cosine law (core), part 1 of 2", or "Not started"
    std::string next;           // "Next: step 3, Cosine-weighted sampling", "Next: part 2 of 2", or "Last step"
    std::string clock;          // "12 min since the lesson opened, 45 planned"
    std::string questionsHeading;         // the lesson's own heading of its questions
    std::vector<std::string> questions;   // the lesson's questions (Markdown)
    std::string notesHeading;   // "Teacher's notes and answers", in the lesson's language
    std::string notes;          // the teacher's notes (Markdown): the answers, timings, pitfalls
};

// `minutesElapsed`: since the lesson was opened.
PresenterContent presenterContent(const LessonSession& lesson, double minutesElapsed);

struct PresenterState {
    bool classMode = false;     // the projector shows no answers: the Lesson panel hides the teacher's notes
    bool show = false;          // the presenter view is shown (F2)
    bool ownWindow = false;     // it is drawn in its own window (--presenter-window), not the main one

    // The content at time `now` (seconds): the clock starts again when another lesson is open.
    PresenterContent content(const LessonSession& lesson, double now);

private:
    std::filesystem::path clockLesson_;
    double clockStart_ = 0.0;
};

} // namespace raylab::ui
