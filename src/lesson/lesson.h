#pragma once
// Lessons: Markdown files in lessons/ (format: lessons/README.md; the Dutch edition in lessons/nl/),
// each tied to a scene, made of sections whose role a marker after the heading names
// (`## Step 2: TITLE {#step .optional}`), and of steps whose ```raylab fenced block holds script
// commands (script/script.h) that set the viewer's state. Parsed with md4c. The viewer's Lesson
// panel shows them; tests load every one.
#include "lesson/section_marker.h"
#include "script/script.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

// "FILE:LINE: error: what" (or "FILE: error: what" when no line applies).
class LessonError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A `## ` heading of the lesson, as written, without its marker.
struct LessonSection {
    LessonRole role = LessonRole::Goals;
    int line = 0;
    std::string heading;                  // "Learning goals", "Leerdoelen", "Step 2: Lambert's cosine law"
};

struct LessonStep {
    int line = 0;                         // line of the "## WORD N: TITLE {#step}" heading
    std::string heading;                  // "WORD N: TITLE" as written ("Step 2: ...", "Stap 2: ...")
    std::string title;                    // TITLE
    bool optional = false;                // the marker is `{#step .optional}`: a class may skip it
    std::string text;                     // the step's Markdown, without its heading and ```raylab block
    std::vector<ScriptCommand> commands;  // the ```raylab block; ScriptCommand::line is the file's line

    // Sub-steps: the block cut at its `hold` lines (1 when it has none); the presenter's key moves
    // from one to the next, so a comparison holds each state for the class.
    int partCount() const;
    // What shows sub-step `part` (0-based): the earlier sub-steps' commands without their waits
    // (their state, not their pictures), then the sub-step's own; `hold` lines left out.
    std::vector<ScriptCommand> partScript(int part) const;
};

// A picture of the lesson's Markdown, `![alt](SOURCE)`.
struct LessonPicture {
    int line = 0;                         // the line it is written on
    std::string source;                   // SOURCE as written: a file relative to the lesson's folder
};

struct Lesson {
    std::filesystem::path file;           // the lesson's Markdown file
    std::filesystem::path root;           // the repository root: the folder above the lesson's folder
    std::string title;                    // the "# " heading
    std::string language = "en";          // "Language:" line: "en" or "nl" (lesson_words.h); "en" if none
    std::string scene;                    // as written after "Scene:", relative to root
    std::filesystem::path scenePath;      // root / scene; the file exists
    int sceneLine = 0;
    std::string level;                    // "Level:" line: "VWO 5–6" or "first-year university" ("" if none)
    int minutes = 0;                      // "Minutes:" line: the planned class time (0 if none)
    std::string introduction;             // Markdown between the title and the first "## " section
    std::vector<LessonSection> sections;  // every "## " heading, in file order
    std::vector<std::string> goals;       // {#goals} list items (Markdown, one line each)
    std::vector<LessonStep> steps;        // {#step} sections, numbered 1, 2, ...
    std::vector<std::string> questions;   // {#questions} list items
    std::string exercise;                 // {#exercise} Markdown
    std::string writeItYourself;          // {#code} Markdown (optional): the code track
    std::vector<std::string> codeExercises;   // the exercises it opens: each `--exercise NAME` in it
    std::string goingFurther;             // {#further} Markdown (optional): notebooks, reading
    std::string teacherNotes;             // {#notes} Markdown (optional)
    std::string sources;                  // {#sources} Markdown (optional)
    std::vector<LessonPicture> pictures;  // every picture, in file order (the files may be missing)

    // A path as a script's `open` gives it, resolved like the scene: relative to root.
    std::filesystem::path resolve(const std::string& path) const;
    // A picture's file: its source relative to the lesson's folder.
    std::filesystem::path picturePath(const std::string& source) const;
    // The heading of the (first) section of `role` as written, else the language's word for it.
    std::string heading(LessonRole role) const;
};

// The levels a "Level:" line may name.
inline constexpr const char* kLessonLevels[] = {"VWO 5\u20136", "first-year university"};

// Parses lesson text; `file` names it in messages and `root` resolves the scene. Throws LessonError
// naming FILE:LINE (script errors in steps included).
Lesson parseLesson(std::string_view text, const std::filesystem::path& file, const std::filesystem::path& root);

// The repository root of a lesson file: the folder above the lesson's folder, or two above for a
// language's edition inside `lessons` (lessons/X.md and lessons/nl/X.md have the same root).
std::filesystem::path lessonRoot(const std::filesystem::path& file);

// Reads `file`; its scene resolves against lessonRoot(file).
Lesson loadLesson(const std::filesystem::path& file);

// Every *.md file of `dir` except README.md, in file-name order.
std::vector<Lesson> loadLessons(const std::filesystem::path& dir);

} // namespace raylab
