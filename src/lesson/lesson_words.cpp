#include "lesson/lesson_words.h"

#include <algorithm>
#include <array>
#include <iterator>

namespace raylab {
namespace {

// One row a word, its translations beside it (the order of kLessonLanguages). Dutch: the terms of
// lessons/nl/README.md's glossary.
struct Row {
    const char* LessonWords::*word;
    const char* text[std::size(kLessonLanguages)];
};

constexpr Row kRows[] = {
    {&LessonWords::languageName, {"English", "Nederlands"}},
    {&LessonWords::goals, {"Learning goals", "Leerdoelen"}},
    {&LessonWords::questions, {"Questions", "Vragen"}},
    {&LessonWords::exercise, {"Exercise", "Opdracht"}},
    {&LessonWords::code, {"Write it yourself", "Schrijf het zelf"}},
    {&LessonWords::further, {"Going further", "Verder"}},
    {&LessonWords::notes, {"Teacher's notes", "Aantekeningen voor de docent"}},
    {&LessonWords::sources, {"Sources", "Bronnen"}},
    {&LessonWords::step, {"Step", "Stap"}},
    {&LessonWords::stepInText, {"step", "stap"}},
    {&LessonWords::of, {"of", "van"}},
    {&LessonWords::part, {"part", "deel"}},
    {&LessonWords::core, {"core", "kern"}},
    {&LessonWords::optional, {"optional", "facultatief"}},
    {&LessonWords::next, {"Next", "Volgende"}},
    {&LessonWords::previous, {"Previous", "Vorige"}},
    {&LessonWords::notStarted, {"Not started", "Nog niet begonnen"}},
    {&LessonWords::lastStep, {"Last step", "Laatste stap"}},
    {&LessonWords::minutes, {"minutes", "minuten"}},
    {&LessonWords::minutesLabel, {"Minutes", "Minuten"}},
    {&LessonWords::minutesSinceOpened, {"min since the lesson opened", "min sinds de les geopend is"}},
    {&LessonWords::planned, {"planned", "gepland"}},
    {&LessonWords::noLessonOpen, {"No lesson open", "Geen les geopend"}},
    {&LessonWords::noNotes, {"This lesson has no teacher's notes.", "Deze les heeft geen aantekeningen voor de docent."}},
    {&LessonWords::notesAndAnswers, {"Teacher's notes and answers", "Aantekeningen voor de docent en antwoorden"}},
    {&LessonWords::chooseLesson, {"Choose a lesson", "Kies een les"}},
    {&LessonWords::doesNotLoad, {"does not load", "laadt niet"}},
    {&LessonWords::panelHelp,
     {"Lessons are Markdown files in lessons/ (raylab --lesson FILE opens one). Each step has a button that sets the "
      "viewer's state; PageDown / PageUp move through the steps.",
      "Lessen zijn Markdown-bestanden in lessons/nl/ (raylab --lesson BESTAND --lang nl opent er een). Elke stap heeft een "
      "knop die de toestand van de viewer instelt; PageDown / PageUp gaan door de stappen."}},
    {&LessonWords::nextHolds, {"Next holds the next state", "Volgende toont de volgende toestand"}},
    {&LessonWords::setsState, {"Sets the viewer's state:", "Zet de toestand van de viewer:"}},
    {&LessonWords::openExercise, {"Open exercise", "Open oefening"}},
    {&LessonWords::notesOnPresenter, {"Teacher's notes: on the presenter view", "Aantekeningen voor de docent: op het presentatorscherm"}},
    {&LessonWords::scene, {"Scene", "Sc\u00e8ne"}},
    {&LessonWords::level, {"Level", "Niveau"}},
    {&LessonWords::worksheet, {"worksheet", "werkblad"}},
    {&LessonWords::teacherSheet, {"teacher's sheet", "docentenblad"}},
    {&LessonWords::teacherSheetHeading, {"Teacher's sheet", "Docentenblad"}},
    {&LessonWords::notGiven, {"not given", "niet opgegeven"}},
    {&LessonWords::steps, {"Steps", "Stappen"}},
    {&LessonWords::name, {"Name", "Naam"}},
    {&LessonWords::className, {"Class", "Klas"}},
    {&LessonWords::date, {"Date", "Datum"}},
    {&LessonWords::inRaylab, {"In raylab", "In raylab"}},
    {&LessonWords::subSteps, {"sub-steps, the presenter's key between them", "deelstappen, met de toets van de presentator ertussen"}},
};
static_assert(std::size(kRows) * sizeof(const char*) == sizeof(LessonWords), "a row for every word");

const std::array<LessonWords, std::size(kLessonLanguages)>& allWords() {
    static const auto words = [] {
        std::array<LessonWords, std::size(kLessonLanguages)> w{};
        for (const Row& row : kRows)
            for (std::size_t l = 0; l < w.size(); ++l) w[l].*row.word = row.text[l];
        return w;
    }();
    return words;
}

} // namespace

bool isLessonLanguage(std::string_view language) {
    return std::find(std::begin(kLessonLanguages), std::end(kLessonLanguages), language) != std::end(kLessonLanguages);
}

std::string lessonLanguageList() {
    std::string s;
    for (const char* l : kLessonLanguages) s += (s.empty() ? "" : ", ") + std::string(l);
    return s;
}

const LessonWords& lessonWords(std::string_view language) {
    const auto it = std::find(std::begin(kLessonLanguages), std::end(kLessonLanguages), language);
    return allWords()[it == std::end(kLessonLanguages) ? 0 : std::size_t(std::distance(std::begin(kLessonLanguages), it))];
}

} // namespace raylab
