// Class mode and the presenter view: the model says where the lesson stands, the time and the
// answers; the Lesson panel in class mode keeps the teacher's notes off the projector while the
// presenter panel shows them; F2 toggles the view; and the real `raylab` opens the presenter in a
// second window beside the projected one, steps the lesson and closes it again.
#include "app/actions.h"
#include "app/presenter.h"
#include "panels/panels.h"

#include "support/panel_frame_test.h"
#include "ui/viewer_run.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

namespace raylab::ui {
namespace {

namespace fs = std::filesystem;

const fs::path kLambert = fs::path(RAYLAB_SOURCE_DIR) / "lessons/07-lambert.md";

class PresenterPanelTest : public test::PanelFrameTest {};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

} // namespace

TEST(Presenter, ContentFollowsTheLessonItsStepsAndTheClock) {
    LessonSession s;
    EXPECT_EQ(presenterContent(s, 0.0).title, "No lesson open");
    ASSERT_FALSE(s.open(kLambert).has_value());
    PresenterContent c = presenterContent(s, 0.0);
    EXPECT_EQ(c.title, s.lesson().title);
    EXPECT_EQ(c.level, s.lesson().level + ", " + std::to_string(s.lesson().minutes) + " minutes");
    EXPECT_EQ(c.step, "Not started");
    EXPECT_EQ(c.next, "Next: step 1, The white furnace (core)");
    EXPECT_EQ(c.questions.size(), s.lesson().questions.size());
    EXPECT_TRUE(contains(c.notes, "L = ρ(1 − F)/(1 − ρF)")) << c.notes;   // the answer to question 3
    ASSERT_TRUE(s.apply(1));
    c = presenterContent(s, 12.4);
    EXPECT_EQ(c.step, "Step 2 of 6: Lambert's cosine law (core)");
    EXPECT_EQ(c.next, "Next: step 3, Cosine-weighted sampling (core)");
    EXPECT_EQ(c.clock, "12 min since the lesson opened, " + std::to_string(s.lesson().minutes) + " planned");
    ASSERT_TRUE(s.apply(5));
    c = presenterContent(s, 40.0);
    EXPECT_EQ(c.step, "Step 6 of 6: What Lambert leaves out (optional)");
    EXPECT_EQ(c.next, "Last step");
    // A step held in parts names the part and the next one.
    for (int i = 0; i < s.stepCount(); ++i)
        if (s.partCount(i) > 1) {
            ASSERT_TRUE(s.apply(i, 0));
            c = presenterContent(s, 0.0);
            EXPECT_TRUE(contains(c.step, ", part 1 of " + std::to_string(s.partCount(i)))) << c.step;
            EXPECT_EQ(c.next, "Next: part 2 of " + std::to_string(s.partCount(i)));
            break;
        }
    // The clock starts when a lesson is first seen and again for another lesson.
    PresenterState state;
    EXPECT_EQ(state.content(s, 100.0).clock.substr(0, 2), "0 ");
    EXPECT_EQ(state.content(s, 100.0 + 5 * 60.0).clock.substr(0, 2), "5 ");
    ASSERT_FALSE(s.open(fs::path(RAYLAB_SOURCE_DIR) / "lessons/03-ray-sphere.md").has_value());
    EXPECT_EQ(state.content(s, 100.0 + 6 * 60.0).clock.substr(0, 2), "0 ");
}

TEST_F(PresenterPanelTest, ClassModeKeepsTheAnswersOffTheLessonPanelAndThePresenterShowsThem) {
    ASSERT_FALSE(ui.lesson.open(kLambert).has_value());
    const std::string open = lessonPanelText();
    EXPECT_TRUE(contains(open, "Teacher's notes")) << open;
    EXPECT_FALSE(contains(open, "on the presenter view"));
    ui.presenter.classMode = true;
    const std::string classMode = lessonPanelText();
    EXPECT_TRUE(contains(classMode, "Teacher's notes: on the presenter view (F2)")) << classMode;
    EXPECT_TRUE(contains(classMode, "Learning goals"));   // the rest of the lesson is there

    ui.lesson.apply(1);
    const std::string presenter = windowText([&] {
        ImGui::SetNextWindowSize(ImVec2(600, 20000));
        ImGui::Begin("presenter");
        drawPresenterPanel(ui);
        ImGui::End();
    });
    EXPECT_TRUE(contains(presenter, "Step 2 of 6: Lambert's cosine law (core)")) << presenter;
    EXPECT_TRUE(contains(presenter, "Teacher's notes and answers"));
    EXPECT_TRUE(contains(presenter, "Q3: the bowl sees itself")) << presenter;
}

TEST_F(PresenterPanelTest, F2TogglesThePresenterPanelOfTheMainWindow) {
    ASSERT_FALSE(ui.lesson.open(kLambert).has_value());
    EXPECT_FALSE(ui.presenter.show);
    runAction(KeyAction::TogglePresenter, *viewer, ui);
    EXPECT_TRUE(ui.presenter.show);
    frame();
    const ImGuiWindow* w = ImGui::FindWindowByName("Presenter");
    ASSERT_NE(w, nullptr);
    EXPECT_TRUE(w->Active);
    runAction(KeyAction::TogglePresenter, *viewer, ui);
    frame();
    EXPECT_FALSE(w->Active);
    // With its own window, the main window draws no Presenter panel.
    ui.presenter.show = true;
    ui.presenter.ownWindow = true;
    frame();
    EXPECT_FALSE(w->Active);
}

TEST(PresenterWindow, OpensBesideTheProjectedWindowStepsTheLessonAndCloses) {
    RAYLAB_START_XVFB(x);
    const fs::path dir = test::windowTestDir("raylab_presenter_window_");
    test_run::ViewerOptions options;
    options.scale = 0.25f;
    options.extraArgs = "--lesson '" + kLambert.string() + "' --class --presenter-window";
    // F2 closes the presenter window and opens it again; the main window keeps running.
    const test_run::ViewerRun run = test_run::runViewer(
        x, dir, "wait-frames 5\nkey page-down\nwait-frames 5\nkey f2\nwait-frames 3\nkey f2\nwait-frames 3\nquit\n",
        (fs::path(RAYLAB_SOURCE_DIR) / "scenes/lesson_one_sphere.json").string(), options);
    ASSERT_EQ(run.status, 0) << run.log;
    std::size_t opened = 0;
    for (auto at = run.log.find("presenter window opened"); at != std::string::npos;
         at = run.log.find("presenter window opened", at + 1))
        ++opened;
    EXPECT_EQ(opened, 2u) << run.log;
    EXPECT_TRUE(contains(run.log, "presenter window closed")) << run.log;
    EXPECT_FALSE(contains(run.log, "error")) << run.log;
}

} // namespace raylab::ui
