#pragma once
// The lesson UI's words: what the Lesson panel, the presenter view and the handouts write
// themselves around a lesson's own text, per language (a lesson's `Language:` line chooses).
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

// The languages a lesson may be written in: `Language: en|nl`, `--lang en|nl`.
inline constexpr const char* kLessonLanguages[] = {"en", "nl"};
inline constexpr const char* kDefaultLessonLanguage = "en";

bool isLessonLanguage(std::string_view language);
// "en, nl": for messages naming the choice.
std::string lessonLanguageList();

struct LessonWords {
    const char* languageName;     // "English", in its own language
    // Section headings, for a section a lesson does not name itself.
    const char* goals;
    const char* questions;
    const char* exercise;
    const char* code;
    const char* further;
    const char* notes;
    const char* sources;
    // Steps and where the lesson stands.
    const char* step;             // "Step" (then a number), starting a heading or a line
    const char* stepInText;       // "step", inside a sentence ("Next: step 3")
    const char* of;               // "step 2 of 6"
    const char* part;             // "part 1 of 2"
    const char* core;
    const char* optional;
    const char* next;
    const char* previous;
    const char* notStarted;
    const char* lastStep;
    const char* minutes;          // "45 minutes"
    const char* minutesLabel;     // "Minutes: 45"
    const char* minutesSinceOpened;   // "12 min since the lesson opened"
    const char* planned;          // ", 45 planned"
    const char* noLessonOpen;
    const char* noNotes;
    const char* notesAndAnswers;  // the presenter's and the teacher's sheet's heading of the notes
    // The Lesson panel.
    const char* chooseLesson;
    const char* doesNotLoad;
    const char* panelHelp;
    const char* nextHolds;        // "(part 1 of 2: Next holds the next state)"
    const char* setsState;        // a step button's tooltip, above its script
    const char* openExercise;
    const char* notesOnPresenter; // class mode: "Teacher's notes: on the presenter view (F2)"
    const char* scene;
    const char* level;
    // The handouts.
    const char* worksheet;
    const char* teacherSheet;     // in the page's title, after the lesson's
    const char* teacherSheetHeading;
    const char* notGiven;
    const char* steps;
    const char* name;
    const char* className;
    const char* date;
    const char* inRaylab;
    const char* subSteps;         // "(3 sub-steps, the presenter's key between them)"
};

// The words of `language`; English for a language it does not know.
const LessonWords& lessonWords(std::string_view language);

} // namespace raylab
