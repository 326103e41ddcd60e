#pragma once
// The Exercise tab's model: the code track's exercises (exercises/manifest.tsv), the one whose
// pupil file the tracer is compiled with, the last compile error and the last checks' verdicts.
// Choosing an exercise or recompiling (F5) goes through Viewer::setTracerDefines, so a compile
// error leaves the previous tracer running.
#include "app/split_screen.h"
#include "app/viewer.h"
#include "exercise/grading.h"
#include "exercise/manifest.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace raylab::ui {

class ExerciseSession {
public:
    // Reads the manifest of the exercises; pupil files are looked for in `pupilDir` (empty: the
    // stubs' folder). Throws std::runtime_error with the manifest's location on a bad row.
    void load(const std::filesystem::path& exerciseDir, const std::filesystem::path& pupilDir = {});
    const std::vector<Exercise>& exercises() const { return exercises_; }

    // Compiles the tracer with exercise `index`'s pupil file (-1: the reference). False when it
    // does not compile: the viewer's document().lastError() has the pupil's lines, and the previous
    // tracer keeps running. F5 (Viewer::reloadShaders) recompiles the same file after an edit.
    bool select(Viewer& viewer, int index);
    int selected() const { return selected_; }
    const Exercise* exercise() const { return selected_ >= 0 ? &exercises_[std::size_t(selected_)] : nullptr; }
    std::filesystem::path pupilFile() const;

    // Runs the selected exercise's checks on the current GL context.
    void check();
    bool checkOnReload = true;   // F5 runs the checks too, after recompiling the tracer
    const std::optional<ExerciseReport>& report() const { return report_; }
    // The render check's pixel where the pupil's render and the reference differ most, in the
    // path inspector: opens the check's scene (unless it is open) and inspects the pixel, scaled to
    // the viewer's resolution, with the pupil's function. False when the check has no pixel or
    // the scene or the inspection fails (the log says why).
    bool inspectDifference(Viewer& viewer, const CheckResult& check) const;
    // The split screen with the pupil's function on the left (A) and the reference on the right
    // (B), at equal samples, on the viewer's scene. False without an exercise.
    bool splitWithReference(Viewer& viewer, SplitScreen& split) const;

private:
    std::vector<Exercise> exercises_;
    std::filesystem::path exerciseDir_, pupilDir_;
    int selected_ = -1;
    std::optional<ExerciseReport> report_;
};

} // namespace raylab::ui
