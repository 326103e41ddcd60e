#include "app/exercise_session.h"

#include <algorithm>

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

bool ExerciseSession::splitWithReference(Viewer& viewer, SplitScreen& split) const {
    if (!exercise()) return false;
    split.stop();
    split.setDefines(0, viewer.runningTracerDefines(), "your function");
    split.setDefines(1, {}, "the reference");
    split.start(SplitBudget::EqualSamples);
    return true;
}

bool ExerciseSession::inspectDifference(Viewer& viewer, const CheckResult& check) const {
    if (check.pixelX < 0 || check.pixelY < 0 || check.scene.empty()) return false;
    const fs::path scene = fs::absolute(check.scene);
    if (viewer.document().path().empty() || fs::absolute(viewer.document().path()) != scene) {
        if (!viewer.openScene(scene)) return false;
    }
    // The check traced the scene at its own resolution; the viewer may trace it scaled.
    const auto scaled = [](int pixel, int from, int to) { return std::min(to - 1, int(float(pixel) * float(to) / float(from))); };
    const int x = scaled(check.pixelX, viewer.scene().render.width, viewer.imageWidth());
    const int y = scaled(check.pixelY, viewer.scene().render.height, viewer.imageHeight());
    return viewer.inspection.inspect(viewer, x, y);
}

} // namespace raylab::ui
