#include "app/presenter.h"

#include <algorithm>
#include <cmath>

namespace raylab::ui {
namespace {

std::string stepTitle(const LessonStep& s, const LessonWords& w) {
    return s.title + " (" + (s.optional ? w.optional : w.core) + ")";
}

// "part 2 of 3"
std::string partOf(int part, int parts, const LessonWords& w) {
    return std::string(w.part) + " " + std::to_string(part) + " " + w.of + " " + std::to_string(parts);
}

} // namespace

PresenterContent presenterContent(const LessonSession& session, double minutesElapsed) {
    PresenterContent c;
    if (!session.isOpen()) {
        c.title = lessonWords(session.language()).noLessonOpen;
        return c;
    }
    const Lesson& l = session.lesson();
    const LessonWords& w = lessonWords(l.language);
    c.title = l.title;
    c.level = l.level;
    if (l.minutes > 0) c.level += (c.level.empty() ? "" : ", ") + std::to_string(l.minutes) + " " + w.minutes;
    const int n = session.stepCount(), cur = session.current();
    const std::string next = std::string(w.next) + ": ";
    if (cur < 0) {
        c.step = w.notStarted;
        c.next = n > 0 ? next + w.stepInText + " 1, " + stepTitle(l.steps.front(), w) : w.lastStep;
    } else {
        const LessonStep& s = l.steps[std::size_t(cur)];
        const int parts = session.partCount(cur), part = session.currentPart();
        c.step = std::string(w.step) + " " + std::to_string(cur + 1) + " " + w.of + " " + std::to_string(n) + ": " + stepTitle(s, w);
        if (parts > 1) c.step += ", " + partOf(part + 1, parts, w);
        if (part + 1 < parts) c.next = next + partOf(part + 2, parts, w);
        else if (cur + 1 < n) c.next = next + w.stepInText + " " + std::to_string(cur + 2) + ", " + stepTitle(l.steps[std::size_t(cur + 1)], w);
        else c.next = w.lastStep;
    }
    const long minutes = std::lround(std::max(0.0, minutesElapsed));
    c.clock = std::to_string(minutes) + " " + w.minutesSinceOpened + (l.minutes > 0 ? ", " + std::to_string(l.minutes) + " " + w.planned : "");
    c.questions = l.questions;
    c.questionsHeading = l.heading(LessonRole::Questions);
    c.notesHeading = w.notesAndAnswers;
    c.notes = l.teacherNotes.empty() ? w.noNotes : l.teacherNotes;
    return c;
}

PresenterContent PresenterState::content(const LessonSession& lesson, double now) {
    const std::filesystem::path file = lesson.isOpen() ? lesson.lesson().file : std::filesystem::path();
    if (file != clockLesson_) {
        clockLesson_ = file;
        clockStart_ = now;
    }
    return presenterContent(lesson, (now - clockStart_) / 60.0);
}

} // namespace raylab::ui
