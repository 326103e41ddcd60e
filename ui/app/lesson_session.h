#pragma once
// The Lesson panel's model: the lessons found in a folder, the open lesson, the step shown, and
// the script a step button (or a presenter key) asks the window loop to run. No ImGui, no GL.
#include "lesson/lesson.h"
#include "lesson/lesson_words.h"
#include "script/script.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace raylab::ui {

// A lesson file found by the picker: its path and "# " title ("" if it does not parse).
struct LessonEntry {
    std::filesystem::path file;
    std::string title;
    std::string error;   // the loader's message when the file does not parse
};

class LessonSession {
public:
    // Lists the *.md lessons (README.md excluded) of the language's edition of the lessons folder
    // `lessons` (lessons/, lessons/nl/; lesson/lesson_edition.h) in file-name order.
    void scan(const std::filesystem::path& lessons);
    const std::vector<LessonEntry>& entries() const { return entries_; }

    // The edition shown: "en" or "nl" (lesson/lesson_words.h); an opened lesson's own language.
    const std::string& language() const { return language_; }
    // Switches the edition: the list is rescanned, and an open lesson reopens in that language at
    // the same step and sub-step, queuing no script (the editions' steps are the same). On failure
    // (an unknown language, a lesson without that translation) nothing changes and the error returns.
    std::optional<std::string> setLanguage(const std::string& language);

    // Opens a lesson; on failure keeps the previous one and returns the error (FILE:LINE).
    std::optional<std::string> open(const std::filesystem::path& file);
    bool isOpen() const { return lesson_.has_value(); }
    const Lesson& lesson() const { return *lesson_; }

    // The step shown (0-based), -1 before the first step is applied; its sub-step (lesson.h).
    int current() const { return current_; }
    int currentPart() const { return part_; }
    int stepCount() const { return isOpen() ? int(lesson_->steps.size()) : 0; }
    int partCount(int step) const;
    // Apply sub-step `part` of step i: it becomes current and its script is queued for the window
    // loop. Out-of-range indices are ignored (false). next()/previous() move by one sub-step
    // (presenter keys): previous() from a step's first sub-step goes to the last of the step before.
    bool apply(int i, int part = 0);
    bool next();
    bool previous();

    // The queued script, once: the viewer state a step does not mention is put back to its default
    // first (beauty view, no overlays, no bounce stepping, no split screen), then the lesson's
    // scene is opened if the step does not start with `open`, then the step's own commands;
    // `open` paths are resolved against the repository root as the lesson format says.
    std::optional<std::vector<ScriptCommand>> takeScript();
    bool hasPending() const { return pending_.has_value(); }

private:
    std::filesystem::path lessons_;   // the folder scanned last ("" before a scan)
    std::string language_ = kDefaultLessonLanguage;
    std::vector<LessonEntry> entries_;
    std::optional<Lesson> lesson_;
    int current_ = -1;
    int part_ = 0;
    std::optional<std::vector<ScriptCommand>> pending_;
};

// lessons/ of the source tree or the installation: the folder beside the shader folder.
std::filesystem::path defaultLessonDirectory(const std::filesystem::path& shaderDirectory);

// The commands that put the viewer state lessons change back to its default (see takeScript).
std::vector<ScriptCommand> lessonResetCommands();

} // namespace raylab::ui
