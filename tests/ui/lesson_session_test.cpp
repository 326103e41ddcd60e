// The Lesson panel's model on a headless viewer: every step of every shipped lesson applied as the
// step button does it (LessonSession → the step's script through ScriptRunner), with no command
// failing; presenter keys move through the steps; a step resets what earlier steps set.
#include "app/lesson_session.h"
#include "app/script_runner.h"

#include "render/render_helpers.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace raylab::ui {
namespace {

namespace fs = std::filesystem;

const fs::path kLessons = fs::path(RAYLAB_SOURCE_DIR) / "lessons";

struct NoWindow : ScriptHost {
    void resizeWindow(int, int) override {}
    void dropFile(const std::string&) override {}
};

class LessonSessionTest : public test::GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        viewer = std::make_unique<Viewer>(log);
        viewer->setResolutionScale(0.125f);   // tiny images: the steps' commands are what is tested
    }
    // Runs the queued step script to its end, tracing in between; returns the failed commands.
    int runQueuedStep() {
        auto script = ui.lesson.takeScript();
        EXPECT_TRUE(script.has_value());
        if (!script) return -1;
        ScriptRunner runner(std::move(*script), 600.0);
        runner.markLessonStep();
        runner.limitWaits(1);   // steps wait for up to 1024 spp; one is enough to run them here
        double t = 0.0;
        for (int frame = 0; frame < 100000 && runner.step(*viewer, ui, host, t); ++frame) {
            if (ui.split.on()) ui.split.update(*viewer, 0.05);
            else viewer->update(0.05);
            t += 0.001;
        }
        return runner.failures();
    }
    Log log{false};
    UiState ui;
    NoWindow host;
    std::unique_ptr<Viewer> viewer;
};

// Every lesson of every edition, as a path below lessons/ ("07-lambert.md", "nl/07-lambert.md"):
// the drift test keeps the editions' commands equal, this runs them.
std::vector<std::string> lessonFiles() {
    std::vector<std::string> names;
    for (const std::string edition : {"", "nl/"})
        for (const auto& e : fs::directory_iterator(kLessons / edition))
            if (e.path().extension() == ".md" && e.path().filename() != "README.md")
                names.push_back(edition + e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class EveryLessonStep : public LessonSessionTest, public testing::WithParamInterface<std::string> {};

} // namespace

TEST_P(EveryLessonStep, AppliesInTheViewer) {
    ASSERT_FALSE(ui.lesson.open(kLessons / GetParam()).has_value());
    ASSERT_GT(ui.lesson.stepCount(), 0);
    for (int i = 0; i < ui.lesson.stepCount(); ++i)
    for (int part = 0; part < ui.lesson.partCount(i); ++part) {
        SCOPED_TRACE("step " + std::to_string(i + 1) + " part " + std::to_string(part + 1));
        ASSERT_TRUE(ui.lesson.apply(i, part));
        EXPECT_EQ(ui.lesson.current(), i);
        EXPECT_EQ(ui.lesson.currentPart(), part);
        EXPECT_EQ(runQueuedStep(), 0) << viewer->document().lastError();   // its expect lines included
        EXPECT_TRUE(viewer->hasScene());
        // A step may end by switching the view (a new accumulation): trace its first pass.
        for (int k = 0; k < 10000 && viewer->tracer()->samplesPerPixel() == 0 && !ui.split.on(); ++k) viewer->update(0.05);
        for (int k = 0; k < 10000 && ui.split.on() && ui.split.minSpp() == 0; ++k) ui.split.update(*viewer, 0.05);
        EXPECT_TRUE(viewer->tracer()->samplesPerPixel() > 0 || ui.split.minSpp() > 0) << "the step's image was traced";
    }
}

INSTANTIATE_TEST_SUITE_P(Lessons, EveryLessonStep, testing::ValuesIn(lessonFiles()),
                         [](const testing::TestParamInfo<std::string>& step) {
                             std::string n = step.param.substr(0, step.param.size() - 3);
                             for (char& ch : n)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return n;
                         });

TEST_F(LessonSessionTest, PresenterKeysStepAndAStepResetsWhatOthersSet) {
    ASSERT_FALSE(ui.lesson.open(kLessons / "05-ray-box-bvh.md").has_value());
    EXPECT_EQ(ui.lesson.current(), -1);
    EXPECT_TRUE(ui.lesson.next());   // PageDown from the title: step 1
    EXPECT_EQ(ui.lesson.current(), 0);
    EXPECT_EQ(runQueuedStep(), 0);
    EXPECT_TRUE(viewer->overlays.boxes);   // step 1 draws every box
    viewer->setDebugView(DebugView::Depth);
    viewer->setBounceStep(2);
    EXPECT_TRUE(ui.lesson.next());
    EXPECT_EQ(runQueuedStep(), 0);
    EXPECT_FALSE(viewer->overlays.boxes);   // step 2 turns them off and shows only the selected one
    EXPECT_TRUE(viewer->overlays.selectedOnly);
    EXPECT_EQ(viewer->debugView(), DebugView::Beauty) << "a step starts from the default view";
    EXPECT_EQ(viewer->bounceStep(), 0);
    EXPECT_TRUE(ui.lesson.previous());
    EXPECT_EQ(ui.lesson.current(), 0);
    ui.lesson.takeScript();
    // Step 4 holds two views: Next shows the second, PageUp from step 5 comes back to it.
    ASSERT_TRUE(ui.lesson.apply(3));
    ASSERT_EQ(ui.lesson.partCount(3), 2);
    EXPECT_TRUE(ui.lesson.next());
    EXPECT_EQ(ui.lesson.current(), 3);
    EXPECT_EQ(ui.lesson.currentPart(), 1);
    EXPECT_EQ(runQueuedStep(), 0);
    EXPECT_EQ(viewer->debugView(), DebugView::Triangles);
    EXPECT_TRUE(ui.lesson.next());
    EXPECT_EQ(ui.lesson.current(), 4);
    EXPECT_EQ(ui.lesson.currentPart(), 0);
    EXPECT_TRUE(ui.lesson.previous());
    EXPECT_EQ(ui.lesson.current(), 3);
    EXPECT_EQ(ui.lesson.currentPart(), 1);
    ui.lesson.takeScript();
    while (ui.lesson.next()) ui.lesson.takeScript();
    EXPECT_EQ(ui.lesson.current(), ui.lesson.stepCount() - 1) << "PageDown stops at the last step";
    EXPECT_FALSE(ui.lesson.apply(99));
}

TEST_F(LessonSessionTest, OpenPathsAreResolvedAgainstTheRepositoryAndBadLessonsKeepTheOpenOne) {
    ASSERT_FALSE(ui.lesson.open(kLessons / "03-ray-sphere.md").has_value());
    ASSERT_TRUE(ui.lesson.apply(0));
    const auto script = ui.lesson.takeScript();
    ASSERT_TRUE(script);
    const auto open = std::find_if(script->begin(), script->end(), [](const ScriptCommand& c) { return c.name == "open"; });
    ASSERT_NE(open, script->end());
    EXPECT_TRUE(fs::path(open->args[0]).is_absolute() || fs::exists(open->args[0])) << open->args[0];
    EXPECT_TRUE(fs::exists(open->args[0]));
    const auto error = ui.lesson.open(kLessons / "no-such-lesson.md");
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("no-such-lesson.md"), std::string::npos);
    EXPECT_EQ(ui.lesson.lesson().file.filename(), "03-ray-sphere.md");
    ui.lesson.scan(kLessons);
    std::size_t files = 0;   // every lesson of the folder, README.md aside
    for (const auto& e : fs::directory_iterator(kLessons))
        files += e.path().extension() == ".md" && e.path().filename() != "README.md";
    EXPECT_GE(files, 12u);
    EXPECT_EQ(ui.lesson.entries().size(), files);
    EXPECT_EQ(ui.lesson.entries()[4].title.rfind("Lesson 5", 0), 0u);
}

} // namespace raylab::ui
