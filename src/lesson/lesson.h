#pragma once
// Lessons: Markdown files in lessons/ (format: lessons/README.md), each tied to a scene, made of
// steps whose ```raylab fenced block holds script commands (script/script.h) that set the viewer's
// state. Parsed with md4c. The viewer's Lesson panel shows them; tests load every one.
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

struct LessonStep {
    int line = 0;                         // line of the "## Step N: TITLE" heading
    std::string title;                    // TITLE, without a trailing "(optional)"
    bool optional = false;                // the heading ends in "(optional)": a class may skip it
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
    std::string scene;                    // as written after "Scene:", relative to root
    std::filesystem::path scenePath;      // root / scene; the file exists
    int sceneLine = 0;
    std::string level;                    // "Level:" line: "VWO 5–6" or "first-year university" ("" if none)
    int minutes = 0;                      // "Minutes:" line: the planned class time (0 if none)
    std::string introduction;             // Markdown between the title and the first "## " section
    std::vector<std::string> goals;       // "## Learning goals" list items (Markdown, one line each)
    std::vector<LessonStep> steps;        // "## Step N: TITLE" sections, N = 1, 2, ...
    std::vector<std::string> questions;   // "## Questions" list items
    std::string exercise;                 // "## Exercise" Markdown
    std::string writeItYourself;          // "## Write it yourself" Markdown (optional): the code track
    std::vector<std::string> codeExercises;   // the exercises it opens: each `--exercise NAME` in it
    std::string goingFurther;             // "## Going further" Markdown (optional): notebooks, reading
    std::string teacherNotes;             // "## Teacher's notes" Markdown (optional)
    std::string sources;                  // "## Sources" Markdown (optional)
    std::vector<LessonPicture> pictures;  // every picture, in file order (the files may be missing)

    // A path as a script's `open` gives it, resolved like the scene: relative to root.
    std::filesystem::path resolve(const std::string& path) const;
    // A picture's file: its source relative to the lesson's folder.
    std::filesystem::path picturePath(const std::string& source) const;
};

// The levels a "Level:" line may name.
inline constexpr const char* kLessonLevels[] = {"VWO 5\u20136", "first-year university"};

// Parses lesson text; `file` names it in messages and `root` resolves the scene. Throws LessonError
// naming FILE:LINE (script errors in steps included).
Lesson parseLesson(std::string_view text, const std::filesystem::path& file, const std::filesystem::path& root);

// Reads `file`; the repository root is the folder above the lesson's folder (lessons/..).
Lesson loadLesson(const std::filesystem::path& file);

// Every *.md file of `dir` except README.md, in file-name order.
std::vector<Lesson> loadLessons(const std::filesystem::path& dir);

} // namespace raylab
