#pragma once
// The lesson UI's words: what the Lesson panel, the presenter view and the handouts write
// themselves around a lesson's own text, per language (a lesson's `Language:` line chooses).
#include <string>
#include <string_view>

namespace raylab {

// The languages a lesson may be written in: `Language: en|nl`, `--lang en|nl`.
inline constexpr const char* kLessonLanguages[] = {"en", "nl"};
inline constexpr const char* kDefaultLessonLanguage = "en";

bool isLessonLanguage(std::string_view language);
// "en, nl": for messages naming the choice.
std::string lessonLanguageList();

// Every member is a word or phrase (lesson_words.cpp gives each with its translations).
struct LessonWords {
    const char* languageName;     // "English", in its own language
    // Section headings, for a section a lesson does not name itself.
    const char *goals, *questions, *exercise, *code, *further, *notes, *sources;
    // Where the lesson stands: "Step 2 of 6: TITLE (core), part 1 of 2", "Next: step 3, ...".
    const char *step, *stepInText, *of, *part, *core, *optional, *next, *previous, *notStarted, *lastStep;
    // "VWO 5–6, 45 minutes", "Minutes: 45", "12 min since the lesson opened, 45 planned".
    const char *minutes, *minutesLabel, *minutesSinceOpened, *planned;
    const char *noLessonOpen, *noNotes, *notesAndAnswers;
    // The Lesson panel: the picker, its help, a held step's hint, a step button's tooltip above its
    // script, the code track's button, class mode's line, the scene and level lines.
    const char *chooseLesson, *doesNotLoad, *panelHelp, *nextHolds, *setsState, *openExercise, *notesOnPresenter, *scene, *level;
    // The handouts: page titles, the teacher's sheet's line, the pupil's name line, the script's caption.
    const char *worksheet, *teacherSheet, *teacherSheetHeading, *notGiven, *steps, *name, *className, *date, *inRaylab, *subSteps;
};

// The words of `language`; English for a language it does not know.
const LessonWords& lessonWords(std::string_view language);

} // namespace raylab
