// The Exercise tab and its model: the tracer runs a pupil's function, F5 after a broken edit keeps
// the previous tracer with the error at the pupil's line, and "Check" gives the verdicts.
#include "panels/panels.h"

#include "support/panel_frame_test.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <filesystem>
#include <fstream>

namespace raylab::ui {
namespace {

namespace fs = std::filesystem;

class ExerciseSessionTest : public test::PanelFrameTest {};

} // namespace

// ctest: slow
TEST_F(ExerciseSessionTest, APupilsFunctionRunsABrokenEditKeepsThePreviousTracerAndChecksGiveVerdicts) {
    const fs::path root = RAYLAB_SOURCE_DIR;
    const fs::path pupil = fs::temp_directory_path() / ("raylab_exercise_pupil_" + std::to_string(::getpid()));
    fs::create_directories(pupil);
    fs::copy_file(root / "exercises/solutions/01-ray-sphere.glsl", pupil / "01-ray-sphere.glsl", fs::copy_options::overwrite_existing);
    ExerciseSession& s = ui.exercise;
    s.load(root / "exercises", pupil);
    ASSERT_EQ(s.exercises().front().name, "ray-sphere");
    ASSERT_TRUE(s.select(*viewer, 0)) << viewer->document().lastError();
    EXPECT_EQ(s.pupilFile(), fs::absolute(pupil / "01-ray-sphere.glsl"));
    const PathTracer* running = viewer->tracer();
    ASSERT_NE(running, nullptr);
    // The pupil breaks line 3 and presses F5: the error names that line, the tracer stays.
    std::ofstream(pupil / "01-ray-sphere.glsl") << "float intersectSphere(Ray ray, vec3 center, float radius, float tMin, float tMax) {\n"
                                                   "    return -1.0;\n    this is not glsl;\n}\n";
    EXPECT_FALSE(viewer->reloadShaders());
    EXPECT_NE(viewer->document().lastError().find("01-ray-sphere.glsl:3"), std::string::npos) << viewer->document().lastError();
    EXPECT_EQ(viewer->tracer(), running);
    ui.showTeach = true;
    ui.teachTab = 3;
    for (int i = 0; i < 2; ++i) frame();
    const ImGuiWindow* teach = ImGui::FindWindowByName("Teach");
    ASSERT_NE(teach, nullptr);
    EXPECT_TRUE(teach->Active);
    // Fixed, F5, Check: every verdict passes; the stub fails.
    fs::copy_file(root / "exercises/solutions/01-ray-sphere.glsl", pupil / "01-ray-sphere.glsl", fs::copy_options::overwrite_existing);
    EXPECT_TRUE(viewer->reloadShaders()) << viewer->document().lastError();
    s.check();
    ASSERT_TRUE(s.report().has_value());
    EXPECT_TRUE(s.report()->pass());
    fs::copy_file(root / "exercises/01-ray-sphere.glsl", pupil / "01-ray-sphere.glsl", fs::copy_options::overwrite_existing);
    s.check();
    EXPECT_FALSE(s.report()->pass());
    frame();
    // Back to the reference.
    EXPECT_TRUE(s.select(*viewer, -1));
    EXPECT_EQ(s.exercise(), nullptr);
    fs::remove_all(pupil);
}

} // namespace raylab::ui
