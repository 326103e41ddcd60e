#include "app/exercise_session.h"

namespace raylab::ui {
namespace fs = std::filesystem;

void ExerciseSession::load(const fs::path& exerciseDir, const fs::path& pupilDir) {
    exercises_ = loadManifest(exerciseDir / "manifest.tsv");
    exerciseDir_ = exerciseDir;
    pupilDir_ = pupilDir.empty() ? exerciseDir : pupilDir;
    selected_ = -1;
    report_.reset();
}

fs::path ExerciseSession::pupilFile() const {
    return exercise() ? fs::absolute(pupilDir_ / exercise()->file) : fs::path();
}

bool ExerciseSession::select(Viewer& viewer, int index) {
    const int previous = selected_;
    selected_ = index >= 0 && index < int(exercises_.size()) ? index : -1;
    report_.reset();
    ShaderDefines defines;
    if (exercise()) defines.emplace_back(exercise()->slot, "\"" + pupilFile().string() + "\"");
    if (viewer.setTracerDefines(defines)) return true;
    if (previous != selected_) viewer.log().info("the tracer keeps the previous function until this one compiles");
    return false;
}

void ExerciseSession::check() {
    if (!exercise()) return;
    report_ = checkExercise(*exercise(), pupilFile());
}

} // namespace raylab::ui
