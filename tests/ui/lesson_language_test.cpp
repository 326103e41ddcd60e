// The lessons' language: the Lesson session switches between a lesson's editions at the same step
// and sub-step (the Teach panel's English / Nederlands choice), the panels and the presenter speak
// the lesson's language, and the real `raylab --lang nl` opens the Dutch lesson and runs its first
// step. On a fixture edition (support/dutch_lesson_fixture.h), so it holds while lessons/nl/ grows.
#include "app/presenter.h"
#include "panels/panels.h"

#include "support/dutch_lesson_fixture.h"
#include "support/panel_frame_test.h"
#include "ui/viewer_run.h"

#include <gtest/gtest.h>

#include <unistd.h>

namespace raylab::ui {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

fs::path scratch(const std::string& name) { return fs::temp_directory_path() / (name + std::to_string(::getpid())); }

class LessonLanguagePanelTest : public test::PanelFrameTest {};

} // namespace

TEST(LessonLanguage, SwitchingReopensTheLessonAtTheSameStepAndSubStep) {
    const fs::path dir = scratch("raylab_lesson_language_");
    const test::DutchLessonFixture f = test::makeDutchLessonFixture(dir, "05-ray-box-bvh.md");
    LessonSession s;
    s.scan(dir / "lessons");
    ASSERT_EQ(s.entries().size(), 1u);
    EXPECT_EQ(s.language(), "en");
    ASSERT_FALSE(s.open(f.english).has_value());
    ASSERT_EQ(s.partCount(3), 2);
    ASSERT_TRUE(s.apply(3, 1));
    s.takeScript();

    ASSERT_EQ(s.setLanguage("nl"), std::nullopt);
    EXPECT_EQ(s.language(), "nl");
    EXPECT_EQ(s.lesson().language, "nl");
    EXPECT_EQ(s.lesson().file, fs::absolute(f.dutch).lexically_normal());
    EXPECT_EQ(s.current(), 3);
    EXPECT_EQ(s.currentPart(), 1);
    EXPECT_FALSE(s.hasPending()) << "the viewer already shows this step: the editions' scripts are the same";
    ASSERT_EQ(s.entries().size(), 1u);
    EXPECT_EQ(s.entries()[0].title.rfind("Les 5", 0), 0u) << "the list is the Dutch edition's";
    const PresenterContent c = presenterContent(s, 3.0);
    EXPECT_EQ(c.step.rfind("Stap 4 van " + std::to_string(s.stepCount()) + ": ", 0), 0u) << c.step;
    EXPECT_TRUE(contains(c.step, "(kern), deel 2 van 2")) << c.step;
    EXPECT_EQ(c.clock, "3 min sinds de les geopend is, 45 gepland");

    const auto unknown = s.setLanguage("fr");
    ASSERT_TRUE(unknown.has_value());
    EXPECT_EQ(*unknown, "unknown lesson language 'fr' (en, nl)");
    EXPECT_EQ(s.language(), "nl");

    ASSERT_EQ(s.setLanguage("en"), std::nullopt);
    EXPECT_EQ(s.lesson().file, fs::absolute(f.english).lexically_normal());
    EXPECT_EQ(s.current(), 3);
    EXPECT_EQ(s.currentPart(), 1);
    EXPECT_EQ(presenterContent(s, 0.0).step.rfind("Step 4 of ", 0), 0u);

    // A lesson its edition lacks: nothing changes.
    fs::remove(f.dutch);
    const auto missing = s.setLanguage("nl");
    ASSERT_TRUE(missing.has_value());
    EXPECT_TRUE(contains(*missing, "nl/05-ray-box-bvh.md: error: cannot read the lesson")) << *missing;
    EXPECT_EQ(s.language(), "en");
    EXPECT_EQ(s.lesson().language, "en");
    EXPECT_EQ(s.current(), 3);
    fs::remove_all(dir);
}

TEST_F(LessonLanguagePanelTest, TheLessonPanelOffersTheChoiceAndSpeaksTheLessonsLanguage) {
    const fs::path dir = scratch("raylab_lesson_language_panel_");
    const test::DutchLessonFixture f = test::makeDutchLessonFixture(dir, "07-lambert.md");
    ASSERT_FALSE(ui.lesson.open(f.dutch).has_value());
    EXPECT_EQ(ui.lesson.language(), "nl") << "an opened lesson's language is the session's";
    ui.lesson.apply(5);
    const std::string nl = lessonPanelText();
    EXPECT_TRUE(contains(nl, "Nederlands")) << nl;
    EXPECT_TRUE(contains(nl, "Leerdoelen"));
    EXPECT_TRUE(contains(nl, "Stap 6: What Lambert leaves out (facultatief)")) << nl;
    EXPECT_TRUE(contains(nl, "stap 6 van 6"));
    EXPECT_TRUE(contains(nl, "Vragen"));
    EXPECT_TRUE(contains(nl, "Aantekeningen voor de docent"));
    EXPECT_FALSE(contains(nl, "{#")) << "markers are the loader's";
    ASSERT_EQ(ui.lesson.setLanguage("en"), std::nullopt);
    const std::string en = lessonPanelText();
    EXPECT_TRUE(contains(en, "English"));
    EXPECT_TRUE(contains(en, "Step 6: What Lambert leaves out (optional)")) << en;
    EXPECT_TRUE(contains(en, "Learning goals"));
    EXPECT_EQ(ui.lesson.current(), 5);
    fs::remove_all(dir);
}

TEST(LessonLanguageWindow, LangNlOpensTheDutchLessonAndRunsItsFirstStep) {
    RAYLAB_START_XVFB(x);
    const fs::path dir = test::windowTestDir("raylab_lesson_language_window_");
    const test::DutchLessonFixture f = test::makeDutchLessonFixture(dir / "repo", "03-ray-sphere.md");
    test_run::ViewerOptions options;
    options.scale = 0.25f;
    options.extraArgs = "--lesson '" + f.english.string() + "' --lang nl";
    // PageDown applies step 1 (the depth view); the script waits for it, then checks its state.
    const test_run::ViewerRun run = test_run::runViewer(x, dir / "run", "wait-frames 2\nkey page-down\nwait-spp 1\nexpect debug-view depth\nquit\n",
                                                        (dir / "repo/scenes/lesson_one_sphere.json").string(), options);
    ASSERT_EQ(run.status, 0) << run.log;
    EXPECT_TRUE(contains(run.log, "lesson Les 3: Ray")) << run.log;
    EXPECT_FALSE(contains(run.log, "error")) << run.log;

    options.extraArgs = "--lesson '" + f.english.string() + "' --lang fr";
    const test_run::ViewerRun bad = test_run::runViewer(x, dir / "bad", "quit\n", (dir / "repo/scenes/lesson_one_sphere.json").string(), options);
    EXPECT_NE(bad.status, 0);
    EXPECT_TRUE(contains(bad.log, "raylab: --lang: unknown language 'fr' (en, nl)")) << bad.log;
    fs::remove_all(dir);
}

} // namespace raylab::ui
