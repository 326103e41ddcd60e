#include "lesson/lesson_words.h"

#include <algorithm>
#include <iterator>

namespace raylab {
namespace {

// Dutch: the terms of dutch_format's glossary (lessons/nl/README.md), "je" to pupils.
constexpr LessonWords kWords[] = {
    {"English", "Learning goals", "Questions", "Exercise", "Write it yourself", "Going further", "Teacher's notes", "Sources",
     "Step", "step", "of", "part", "core", "optional", "Next", "Previous", "Not started", "Last step", "minutes", "Minutes",
     "min since the lesson opened", "planned", "No lesson open", "This lesson has no teacher's notes.",
     "Teacher's notes and answers", "Choose a lesson", "does not load",
     "Lessons are Markdown files in lessons/ (raylab --lesson FILE opens one). Each step has a button that sets the "
     "viewer's state; PageDown / PageUp move through the steps.",
     "Next holds the next state", "Sets the viewer's state:", "Open exercise", "Teacher's notes: on the presenter view", "Scene",
     "Level", "worksheet", "teacher's sheet", "Teacher's sheet", "not given", "Steps", "Name", "Class", "Date", "In raylab",
     "sub-steps, the presenter's key between them"},
    {"Nederlands", "Leerdoelen", "Vragen", "Opdracht", "Schrijf het zelf", "Verder", "Aantekeningen voor de docent", "Bronnen",
     "Stap", "stap", "van", "deel", "kern", "facultatief", "Volgende", "Vorige", "Nog niet begonnen", "Laatste stap", "minuten", "Minuten",
     "min sinds de les geopend is", "gepland", "Geen les geopend", "Deze les heeft geen aantekeningen voor de docent.",
     "Aantekeningen voor de docent en antwoorden", "Kies een les", "laadt niet",
     "Lessen zijn Markdown-bestanden in lessons/nl/ (raylab --lesson BESTAND --lang nl opent er een). Elke stap heeft een "
     "knop die de toestand van de viewer instelt; PageDown / PageUp gaan door de stappen.",
     "Volgende toont de volgende toestand", "Zet de toestand van de viewer:", "Open oefening",
     "Aantekeningen voor de docent: op het presentatorscherm", "Sc\u00e8ne", "Niveau", "werkblad", "docentenblad", "Docentenblad",
     "niet opgegeven", "Stappen", "Naam", "Klas", "Datum", "In raylab", "deelstappen, met de toets van de presentator ertussen"},
};
static_assert(std::size(kWords) == std::size(kLessonLanguages), "one table of words per language");

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
    return kWords[it == std::end(kLessonLanguages) ? 0 : std::distance(std::begin(kLessonLanguages), it)];
}

} // namespace raylab
