#pragma once
// Grading the code track: one pupil's file for an exercise through all of its checks, and a
// folder of pupils' files into a table per pupil and exercise (raylab-exercise check).
#include "exercise/checks.h"
#include "exercise/manifest.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct ExerciseReport {
    std::string exercise;
    std::filesystem::path file;
    bool compiled = false;
    std::string compileError;   // the compiler's messages at the pupil file's own lines
    std::vector<CheckResult> checks;
    bool pass() const;
};

// Compiles `pupilFile` into the exercise's slot and runs its checks; pictures (the render check's
// difference image) go to imageDir unless it is empty. Needs a current GL context.
ExerciseReport checkExercise(const Exercise& exercise, const std::filesystem::path& pupilFile,
                             const std::filesystem::path& imageDir = {});

struct PupilReport {
    std::string pupil;   // the sub-folder's name, or the folder's for one pupil's files
    std::vector<ExerciseReport> exercises;
};

// `dir` holds one pupil's files (named as the manifest's file column), or one sub-folder per
// pupil. Throws std::runtime_error naming the path when there is no such folder or no pupil file.
// Pictures go to imageDir/<pupil>/ unless imageDir is empty.
std::vector<PupilReport> gradeFolder(const std::filesystem::path& dir, const std::vector<Exercise>& exercises,
                                     const std::filesystem::path& imageDir = {});

std::string reportMarkdown(const std::vector<PupilReport>& pupils);
std::string reportCsv(const std::vector<PupilReport>& pupils);

} // namespace raylab
