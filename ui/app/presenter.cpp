#include "app/presenter.h"

#include <algorithm>
#include <cmath>

namespace raylab::ui {
namespace {

std::string stepTitle(const LessonStep& s) { return s.title + (s.optional ? " (optional)" : " (core)"); }

} // namespace

PresenterContent presenterContent(const LessonSession& session, double minutesElapsed) {
    PresenterContent c;
    if (!session.isOpen()) {
        c.title = "No lesson open";
        return c;
    }
    const Lesson& l = session.lesson();
    c.title = l.title;
    c.level = l.level;
    if (l.minutes > 0) c.level += (c.level.empty() ? "" : ", ") + std::to_string(l.minutes) + " minutes";
    const int n = session.stepCount(), cur = session.current();
    if (cur < 0) {
        c.step = "Not started";
        c.next = n > 0 ? "Next: step 1, " + stepTitle(l.steps.front()) : "Last step";
    } else {
        const LessonStep& s = l.steps[std::size_t(cur)];
        const int parts = session.partCount(cur), part = session.currentPart();
        c.step = "Step " + std::to_string(cur + 1) + " of " + std::to_string(n) + ": " + stepTitle(s);
        if (parts > 1) c.step += ", part " + std::to_string(part + 1) + " of " + std::to_string(parts);
        if (part + 1 < parts) c.next = "Next: part " + std::to_string(part + 2) + " of " + std::to_string(parts);
        else if (cur + 1 < n) c.next = "Next: step " + std::to_string(cur + 2) + ", " + stepTitle(l.steps[std::size_t(cur + 1)]);
        else c.next = "Last step";
    }
    const long minutes = std::lround(std::max(0.0, minutesElapsed));
    c.clock = std::to_string(minutes) + " min since the lesson opened" + (l.minutes > 0 ? ", " + std::to_string(l.minutes) + " planned" : "");
    c.questions = l.questions;
    c.notes = l.teacherNotes.empty() ? "This lesson has no teacher's notes." : l.teacherNotes;
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
