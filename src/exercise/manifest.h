#pragma once
// The code track's exercises as exercises/manifest.tsv lists them: which slot of the tracer a
// pupil's file replaces, where the stub is, its level, the time it takes and the checks that grade
// it (exercises/README.md).
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct Exercise {
    std::string name;                  // "ray-sphere"
    std::string slot;                  // the tracer's file define, RAYLAB_EXERCISE_RAY_SPHERE
    std::string file;                  // the pupil's file name, "01-ray-sphere.glsl"
    std::string level;                 // "VWO 5-6" or "first-year university"
    int minutes = 0;                   // estimated time
    std::vector<std::string> checks;   // names in exerciseChecks() (exercise/checks.h)
};

// Where the exercises live: $RAYLAB_EXERCISE_DIR, else <exe>/../share/raylab/exercises, else the
// source tree's exercises/.
std::filesystem::path exerciseDirectory();

// Reads a manifest; a bad row throws std::runtime_error naming file:line:col and what is wrong
// (an unknown slot or check, a duplicate name, a missing column, minutes that are not a number).
std::vector<Exercise> loadManifest(const std::filesystem::path& file);
std::vector<Exercise> loadManifest();   // exerciseDirectory() / "manifest.tsv"

// The exercise called `name`, or nullptr.
const Exercise* findExercise(const std::vector<Exercise>& exercises, const std::string& name);

} // namespace raylab
