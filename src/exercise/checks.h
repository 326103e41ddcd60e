#pragma once
// The code track's checks: each runs a pupil's slot function through the exercise probe on a
// fixed set of inputs and ends in a verdict with the numbers, and where a known mistake explains
// the results, a message that names it (exercises/README.md lists them per exercise).
#include "exercise/exercise_probe.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

struct CheckResult {
    CheckResult() = default;
    CheckResult(std::string check_, bool pass_, std::string numbers_, std::string message_ = {}, std::string image_ = {})
        : check(std::move(check_)), pass(pass_), numbers(std::move(numbers_)), message(std::move(message_)), image(std::move(image_)) {}

    std::string check;     // the check's name in the manifest
    bool pass = false;
    std::string numbers;   // what was measured, e.g. "0 of 212 rays wrong, max |Δt| 3e-7"
    std::string message;   // on a failure: what is wrong and, where known, which mistake it is
    std::string image;     // a picture the check wrote (the render check's difference image), or ""
    // The render check: the pixel of `scene` (top-left origin) the path inspector was run on, where
    // the two renders differ most; -1 when it was not (the check passed).
    int pixelX = -1;
    int pixelY = -1;
    std::string scene;
};

// What a check gets: the probe compiled with the pupil's file, and the file itself for checks
// that compile the whole tracer with it.
struct CheckContext {
    const ExerciseProbe& probe;
    std::string slot;                  // the exercise's file define
    std::filesystem::path pupilFile;
    std::string exercise;              // its name, for the names of pictures
    std::filesystem::path imageDir;    // where pictures go; empty: none are written
};

using ExerciseCheckFn = CheckResult (*)(const CheckContext& context);

struct ExerciseCheck {
    const char* name;
    ExerciseCheckFn run;
    const char* what;   // one line for `raylab-exercise list`
};

const std::vector<ExerciseCheck>& exerciseChecks();
const ExerciseCheck* findExerciseCheck(const std::string& name);

// The checks, one family per file (intersection_checks.cpp, sampling_checks.cpp, brdf_checks.cpp,
// lens_checks.cpp, mean_checks.cpp, render_checks.cpp).
CheckResult checkSphereRays(const ExerciseProbe& probe);
CheckResult checkTriangleRays(const ExerciseProbe& probe);
CheckResult checkWatertight(const ExerciseProbe& probe);
CheckResult checkBoxRays(const ExerciseProbe& probe);
CheckResult checkHemispherePdf(const ExerciseProbe& probe);
CheckResult checkHemisphereChi2(const ExerciseProbe& probe);
CheckResult checkLambertPointwise(const ExerciseProbe& probe);
CheckResult checkLambertFurnace(const ExerciseProbe& probe);
CheckResult checkLambertReciprocity(const ExerciseProbe& probe);
CheckResult checkGgxDPointwise(const ExerciseProbe& probe);
CheckResult checkGgxDNormalisation(const ExerciseProbe& probe);
CheckResult checkSmithGPointwise(const ExerciseProbe& probe);
CheckResult checkSmithGVisibleNormals(const ExerciseProbe& probe);
CheckResult checkSchlickPointwise(const ExerciseProbe& probe);
CheckResult checkLensFocus(const ExerciseProbe& probe);
CheckResult checkLensDisk(const ExerciseProbe& probe);
CheckResult checkMeanSequences(const ExerciseProbe& probe);
CheckResult checkRenderDiff(const CheckContext& context);

} // namespace raylab
