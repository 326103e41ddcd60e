#pragma once
// Handouts: a lesson as one self-contained, printable HTML page (CSS inline, pictures as data:
// URIs). The pupil's worksheet leaves out the answers (the teacher's notes) and keeps room to
// write; the teacher's sheet adds the level, the minutes, each step's core or optional mark and
// script, and the teacher's notes.
#include "lesson/lesson.h"

#include <string>

namespace raylab {

enum class LessonSheet { Pupil, Teacher };

// Throws LessonError "FILE:LINE: error: ..." when a picture cannot be read.
std::string lessonSheetHtml(const Lesson& lesson, LessonSheet sheet);

} // namespace raylab
