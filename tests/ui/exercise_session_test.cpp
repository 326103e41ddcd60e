// The Exercise tab and its model: the tracer runs a pupil's function, F5 after a broken edit keeps
// the previous tracer with the error at the pupil's line, "Check" (and F5) gives the verdicts, and
// a failed render check opens the path inspector at its pixel with the pupil's function, and the
// split screen shows the pupil's render beside the reference's.
#include "app/actions.h"
#include "panels/panels.h"

#include "inspect/path_inspector.h"
#include "render/progressive_render.h"

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

// ctest: slow
TEST_F(ExerciseSessionTest, F5ChecksAndAFailedRenderCheckInspectsItsPixelWithThePupilsFunction) {
    const fs::path root = RAYLAB_SOURCE_DIR;
    const fs::path pupil = fs::temp_directory_path() / ("raylab_exercise_inspect_" + std::to_string(::getpid()));
    fs::create_directories(pupil);
    // A lens twice as wide as it should be (the wrong answer thin-lens/diameter).
    std::ifstream in(root / "exercises/solutions/09-thin-lens.glsl");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string from = "vec2 lens = lensRadius *";
    ASSERT_NE(text.find(from), std::string::npos);
    text.replace(text.find(from), from.size(), "vec2 lens = 2.0 * lensRadius *");
    std::ofstream(pupil / "09-thin-lens.glsl") << text;
    ExerciseSession& s = ui.exercise;
    s.load(root / "exercises", pupil);
    int index = -1;
    for (int i = 0; i < int(s.exercises().size()); ++i)
        if (s.exercises()[std::size_t(i)].name == "thin-lens") index = i;
    ASSERT_GE(index, 0);
    ASSERT_TRUE(s.select(*viewer, index)) << viewer->document().lastError();
    EXPECT_FALSE(s.report().has_value());
    runAction(KeyAction::ReloadShaders, *viewer, ui);   // F5 recompiles and checks
    ASSERT_TRUE(s.report().has_value());
    const CheckResult* render = nullptr;
    for (const CheckResult& c : s.report()->checks)
        if (c.check == "render-diff") render = &c;
    ASSERT_NE(render, nullptr);
    ASSERT_FALSE(render->pass) << render->numbers;
    ASSERT_GE(render->pixelX, 0);
    EXPECT_NE(render->message.find("the path inspector at pixel"), std::string::npos) << render->message;
    EXPECT_NE(render->message.find("the ray's origin is"), std::string::npos) << render->message;
    const std::string panel = windowText([&] {
        ImGui::Begin("exercise");
        drawExercisePanel(*viewer, ui);
        ImGui::End();
    });
    EXPECT_NE(panel.find("Inspect pixel (" + std::to_string(render->pixelX) + ", " + std::to_string(render->pixelY) + ")"),
              std::string::npos)
        << panel;

    // The button's action: the check's scene opens and its pixel is inspected with the pupil's lens.
    ASSERT_TRUE(s.inspectDifference(*viewer, *render));
    EXPECT_EQ(fs::absolute(viewer->document().path()), fs::absolute(root / "exercises/render_check.json"));
    ASSERT_TRUE(viewer->inspection.active());
    ASSERT_FALSE(viewer->inspection.paths().empty());
    const PathRecord& shown = viewer->inspection.paths().front();
    const auto cameraOrigin = [&](const ShaderDefines& defines) {
        PathInspector inspector(PathInspector::kDefaultMaxRecords, defines);
        inspector.setScene(viewer->tracedScene());
        return inspector.record(viewer->inspection.x(), viewer->inspection.y(), 1, shown.sample).front().bounces.front().origin;
    };
    EXPECT_EQ(shown.bounces.front().origin, cameraOrigin(viewer->runningTracerDefines()));
    EXPECT_NE(shown.bounces.front().origin, cameraOrigin({}));   // the reference's lens is another

    // Yours | the reference in the split screen at equal samples: each side is the image of a
    // tracer compiled with that side's function.
    ASSERT_TRUE(viewer->document().set("render.spp", "4"));
    ASSERT_TRUE(s.splitWithReference(*viewer, ui.split));
    for (int i = 0; i < 400 && !ui.split.converged(); ++i) ui.split.update(*viewer, 0.05);
    ASSERT_TRUE(ui.split.converged()) << ui.split.lastError();
    EXPECT_EQ(ui.split.label(0), "A: your function");
    EXPECT_EQ(ui.split.label(1), "B: the reference");
    const auto renderWith = [&](const ShaderDefines& defines) {
        TracerOptions o;
        o.extraDefines = defines;
        PathTracer t(o);
        Scene sc = viewer->scene();
        sc.render.width = viewer->imageWidth();
        sc.render.height = viewer->imageHeight();
        t.setScene(sc);
        renderProgressively(t, sc.render);
        return t.readImage().rgba;
    };
    EXPECT_EQ(ui.split.image(0).rgba, renderWith(viewer->runningTracerDefines()));
    EXPECT_EQ(ui.split.image(1).rgba, renderWith({}));
    EXPECT_NE(ui.split.image(0).rgba, ui.split.image(1).rgba);
    ui.split.stop();
    EXPECT_EQ(ui.split.label(0), "A: as the scene");
    fs::remove_all(pupil);
}

} // namespace raylab::ui
