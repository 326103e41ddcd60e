// The lesson format (lessons/README.md): a well-formed lesson gives its parts, and each kind of
// mistake is an error naming FILE:LINE.
#include "lesson/lesson.h"
#include "script/script.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kRoot = fs::path(RAYLAB_SOURCE_DIR);

// A complete lesson; tests change one thing in it.
const std::string kGood = R"(# Lesson 0: A test

Scene: scenes/default.json

An *introduction* paragraph.

## Learning goals {#goals}

- Say what a `ray` is.
- Count to two.

## Step 1: Look {#step}
Some text.

```raylab
open scenes/default.json
debug-view normals
```

More text after the block.

## Step 2: Change {#step}
```raylab
set camera.fov 50
reset
wait-spp 4
```

## Questions {#questions}

1. Why?
2. Why not,
   on two lines?

## Exercise {#exercise}

Do it.

## Going further {#further}

Open `notebooks/x.ipynb`.

## Sources {#sources}

- Kajiya 1986.
)";

std::string errorOf(const std::string& text) {
    try {
        parseLesson(text, "lessons/t.md", kRoot);
    } catch (const LessonError& e) {
        return e.what();
    }
    return "<no error>";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

} // namespace

TEST(Lesson, ParsesEveryPart) {
    const Lesson l = parseLesson(kGood, "lessons/t.md", kRoot);
    EXPECT_EQ(l.title, "Lesson 0: A test");
    EXPECT_EQ(l.scene, "scenes/default.json");
    EXPECT_EQ(l.sceneLine, 3);
    EXPECT_EQ(l.scenePath, (kRoot / "scenes/default.json").lexically_normal());
    EXPECT_EQ(l.introduction, "An *introduction* paragraph.");
    ASSERT_EQ(l.goals.size(), 2u);
    EXPECT_EQ(l.goals[0], "Say what a `ray` is.");
    ASSERT_EQ(l.steps.size(), 2u);
    EXPECT_EQ(l.steps[0].title, "Look");
    EXPECT_EQ(l.steps[0].line, 12);
    EXPECT_EQ(l.steps[0].text, "Some text.\n\nMore text after the block.");
    ASSERT_EQ(l.steps[0].commands.size(), 2u);
    EXPECT_EQ(l.steps[0].commands[0].name, "open");
    EXPECT_EQ(l.steps[0].commands[0].line, 16);   // the file's line, not the block's
    EXPECT_EQ(l.steps[0].commands[1].args.at(0), "normals");
    ASSERT_EQ(l.steps[1].commands.size(), 3u);
    EXPECT_EQ(l.steps[1].commands[0].args.at(1), "50");
    EXPECT_EQ(l.steps[1].text, "");
    ASSERT_EQ(l.questions.size(), 2u);
    EXPECT_EQ(l.questions[1], "Why not, on two lines?");
    EXPECT_EQ(l.exercise, "Do it.");
    EXPECT_EQ(l.goingFurther, "Open `notebooks/x.ipynb`.");
    EXPECT_EQ(l.sources, "- Kajiya 1986.");
    EXPECT_EQ(l.resolve("scenes/furnace.json"), (kRoot / "scenes/furnace.json").lexically_normal());
}

TEST(Lesson, WriteItYourselfNamesTheExercisesItOpens) {
    const Lesson l = parseLesson(replaced(kGood, "## Going further",
                                          "## Write it yourself {#code}\n\nRun `raylab --exercise ray-sphere`, then\n"
                                          "`raylab --exercise slab-test --exercise-dir mine` and `--exercise ray-sphere` again.\n\n"
                                          "## Going further"),
                                 "lessons/t.md", kRoot);
    EXPECT_NE(l.writeItYourself.find("--exercise slab-test"), std::string::npos) << l.writeItYourself;
    EXPECT_EQ(l.codeExercises, (std::vector<std::string>{"ray-sphere", "slab-test"}));
    EXPECT_EQ(l.goingFurther, "Open `notebooks/x.ipynb`.");
    EXPECT_TRUE(parseLesson(kGood, "lessons/t.md", kRoot).codeExercises.empty());
}

TEST(Lesson, BadCommandNamesFileAndLine) {
    std::string views;
    for (std::string_view v : scriptDebugViews()) views += (views.empty() ? "" : ", ") + std::string(v);
    EXPECT_EQ(errorOf(replaced(kGood, "debug-view normals", "debug-view heat")),
              "lessons/t.md:17: error: unknown debug view 'heat' (" + views + ")");
    EXPECT_EQ(errorOf(replaced(kGood, "wait-spp 4", "wait-sp 4")), "lessons/t.md:26: error: unknown command 'wait-sp'");
}

TEST(Lesson, MissingSceneNamesFileAndLine) {
    EXPECT_EQ(errorOf(replaced(kGood, "Scene: scenes/default.json", "Scene: scenes/nope.json")),
              "lessons/t.md:3: error: scene 'scenes/nope.json' not found (" +
                  (kRoot / "scenes/nope.json").lexically_normal().string() + ")");
    EXPECT_EQ(errorOf(replaced(kGood, "Scene: scenes/default.json\n", "")),
              "lessons/t.md:1: error: no 'Scene: PATH' line under the title");
    EXPECT_EQ(errorOf(replaced(kGood, "Scene: scenes/default.json", "Scene:")),
              "lessons/t.md:3: error: 'Scene:' needs a path (relative to the repository root)");
}

TEST(Lesson, UnclosedFenceNamesItsOpeningLine) {
    // Cut the file after the second step's commands: its fence never closes.
    const std::string cut = kGood.substr(0, kGood.find("wait-spp 4\n") + 11);
    EXPECT_EQ(errorOf(cut), "lessons/t.md:23: error: unclosed code fence (it runs to the end of the file)");
    EXPECT_EQ(errorOf(replaced(kGood, "Do it.", "```glsl\nfloat x;\n")),
              "lessons/t.md:37: error: unclosed code fence (it runs to the end of the file)");
}

TEST(Lesson, StructureMistakesNameFileAndLine) {
    EXPECT_EQ(errorOf(replaced(kGood, "## Step 2: Change", "## Step 3: Change")),
              "lessons/t.md:22: error: step numbered 3, expected 2");
    // A number too large for an int (a fuzzer's find: it overflowed while being read).
    EXPECT_EQ(errorOf(replaced(kGood, "## Step 2: Change", "## Step 4222222222222222: Change")),
              "lessons/t.md:22: error: step numbered above 9999, expected 2");
    EXPECT_EQ(errorOf(replaced(kGood, "```raylab\nset", "```text\nset")),
              "lessons/t.md:22: error: step 2 has no ```raylab block");
    EXPECT_EQ(errorOf(replaced(kGood, "Some text.", "```raylab\nreset\n```")),
              "lessons/t.md:17: error: a second ```raylab block in step 1 (one per step)");
    EXPECT_EQ(errorOf(replaced(kGood, "An *introduction* paragraph.", "```raylab\nreset\n```")),
              "lessons/t.md:5: error: a ```raylab block outside a {#step} section");
    EXPECT_EQ(errorOf(replaced(kGood, "- Say what a `ray` is.\n- Count to two.\n", "Nothing.\n")),
              "lessons/t.md:7: error: no learning goals (a {#goals} section's list)");
    EXPECT_EQ(errorOf(replaced(kGood, "Do it.", "")), "lessons/t.md:35: error: no exercise (a {#exercise} section)");
    EXPECT_EQ(errorOf(replaced(kGood, "## Sources", "# Sources")),
              "lessons/t.md:43: error: a second '# ' title; a lesson has one, sections are '## '");
    EXPECT_EQ(errorOf("Text first.\n\n## Step 1: x\n"), "lessons/t.md:3: error: the lesson must start with a '# TITLE' heading");
    EXPECT_EQ(errorOf(replaced(kGood, "## Questions {#questions}", "Questions {#questions}\n---------")),
              "lessons/t.md:29: error: write headings as '# ' and '## ', not underlined");
}

TEST(Lesson, LoadLessonResolvesAgainstTheFolderAboveAndListsInNameOrder) {
    const fs::path dir = fs::temp_directory_path() / "raylab_lesson_test";
    fs::remove_all(dir);
    fs::create_directories(dir / "lessons");
    fs::create_directories(dir / "scenes");
    fs::copy_file(kRoot / "scenes/default.json", dir / "scenes/default.json");
    for (const char* name : {"02-b.md", "01-a.md", "10-c.md"}) {
        std::ofstream(dir / "lessons" / name) << replaced(kGood, "A test", name);
    }
    std::ofstream(dir / "lessons/README.md") << "# not a lesson\n";
    const auto lessons = loadLessons(dir / "lessons");
    ASSERT_EQ(lessons.size(), 3u);
    EXPECT_EQ(lessons[0].title, "Lesson 0: 01-a.md");
    EXPECT_EQ(lessons[1].title, "Lesson 0: 02-b.md");
    EXPECT_EQ(lessons[2].title, "Lesson 0: 10-c.md");
    EXPECT_EQ(lessons[0].scenePath, (dir / "scenes/default.json").lexically_normal());

    std::ofstream(dir / "lessons/03-bad.md") << replaced(kGood, "reset\nwait", "reset now\nwait");
    try {
        loadLessons(dir / "lessons");
        FAIL() << "no error";
    } catch (const LessonError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "lessons/03-bad.md").string() +
                                             ":25: error: reset takes 0 argument(s), got 1");
    }
    fs::remove_all(dir);
}

TEST(Lesson, HoldCutsAStepIntoSubSteps) {
    const Lesson l = parseLesson(replaced(kGood, "reset\nwait-spp 4\n",
                                          "reset\nwait-spp 4\nexpect camera.fov 50\nhold\nset camera.fov 60\n"
                                          "wait-spp 8\nexpect camera.fov 60\n"),
                                 "lessons/t.md", kRoot);
    EXPECT_EQ(l.steps[0].partCount(), 1);
    ASSERT_EQ(l.steps[1].partCount(), 2);
    auto names = [](const std::vector<ScriptCommand>& script) {
        std::string s;
        for (const ScriptCommand& c : script) s += c.name + (c.args.empty() ? "" : " " + c.args.back()) + "; ";
        return s;
    };
    EXPECT_EQ(names(l.steps[1].partScript(0)), "set 50; reset; wait-spp 4; expect 50; ");
    // The second sub-step replays the first one's state without its waits, then its own commands.
    EXPECT_EQ(names(l.steps[1].partScript(1)), "set 50; reset; expect 50; set 60; wait-spp 8; expect 60; ");
    EXPECT_EQ(errorOf(replaced(kGood, "reset\nwait-spp 4\n", "reset\nwait-spp 4\nhold\n")),
              "lessons/t.md:27: error: hold with no commands after it (it separates sub-steps)");
    EXPECT_EQ(errorOf(replaced(kGood, "```raylab\nset", "```raylab\nhold\nset")),
              "lessons/t.md:24: error: hold with no commands before it (it separates sub-steps)");
    EXPECT_EQ(errorOf(replaced(kGood, "reset\nwait", "reset\nhold\nhold\nwait")),
              "lessons/t.md:26: error: hold with no commands after it (it separates sub-steps)");
}

TEST(Lesson, LevelMinutesAndOptionalSteps) {
    const std::string text = replaced(replaced(kGood, "Scene: scenes/default.json\n",
                                               "Scene: scenes/default.json\n\nLevel: first-year university\n\nMinutes: 45\n"),
                                      "## Step 2: Change {#step}", "## Step 2: Change {#step .optional}");
    const Lesson l = parseLesson(text, "lessons/t.md", kRoot);
    EXPECT_EQ(l.level, "first-year university");
    EXPECT_EQ(l.minutes, 45);
    EXPECT_EQ(l.introduction, "An *introduction* paragraph.") << "the lines are not part of the introduction";
    EXPECT_FALSE(l.steps[0].optional);
    EXPECT_TRUE(l.steps[1].optional);
    EXPECT_EQ(l.steps[1].title, "Change");
    const Lesson none = parseLesson(kGood, "lessons/t.md", kRoot);
    EXPECT_EQ(none.level, "");
    EXPECT_EQ(none.minutes, 0);
    EXPECT_EQ(errorOf(replaced(text, "Level: first-year university", "Level: hard")),
              "lessons/t.md:5: error: 'Level:' is 'VWO 5\u20136' or 'first-year university'");
    EXPECT_EQ(errorOf(replaced(text, "Minutes: 45", "Minutes: a lot")),
              "lessons/t.md:7: error: 'Minutes:' needs the class time in whole minutes");
    EXPECT_EQ(errorOf(replaced(text, "Minutes: 45\n", "Minutes: 45\nLevel: VWO 5\u20136\n")),
              "lessons/t.md:7: error: 'Minutes: ...' must be a paragraph of its own");
}

TEST(Lesson, RolesComeFromMarkersAndHeadingsStayAsWritten) {
    std::string nl = replaced(kGood, "Scene: scenes/default.json\n", "Scene: scenes/default.json\n\nLanguage: nl\n");
    for (const auto& [from, to] : {std::pair{"## Learning goals {#goals}", "## Leerdoelen {#goals}"},
                                   {"## Step 1: Look {#step}", "## Stap 1: Kijk {#step}"},
                                   {"## Step 2: Change {#step}", "## Stap 2: Verander {#step .optional}"},
                                   {"## Questions {#questions}", "## Vragen {#questions}"},
                                   {"## Exercise {#exercise}", "## Opdracht {#exercise}"},
                                   {"## Going further {#further}", "## Verder {#further}"},
                                   {"## Sources {#sources}", "## Bronnen {#sources}"}})
        nl = replaced(nl, from, to);
    const Lesson l = parseLesson(nl, "lessons/nl/t.md", kRoot);
    EXPECT_EQ(l.language, "nl");
    EXPECT_EQ(l.introduction, "An *introduction* paragraph.") << "the Language line is not part of it";
    EXPECT_EQ(l.goals.size(), 2u);
    ASSERT_EQ(l.steps.size(), 2u);
    EXPECT_EQ(l.steps[0].heading, "Stap 1: Kijk");
    EXPECT_EQ(l.steps[0].title, "Kijk");
    EXPECT_FALSE(l.steps[0].optional);
    EXPECT_EQ(l.steps[1].heading, "Stap 2: Verander");
    EXPECT_TRUE(l.steps[1].optional);
    EXPECT_EQ(l.questions.size(), 2u);
    EXPECT_EQ(l.exercise, "Do it.");
    EXPECT_EQ(l.sources, "- Kajiya 1986.");
    std::string roles;
    for (const LessonSection& s : l.sections) roles += roleMarker(s.role) + " " + std::to_string(s.line) + " " + s.heading + "; ";
    EXPECT_EQ(roles, "{#goals} 9 Leerdoelen; {#step} 14 Stap 1: Kijk; {#step} 24 Stap 2: Verander; {#questions} 31 Vragen; "
                     "{#exercise} 37 Opdracht; {#further} 41 Verder; {#sources} 45 Bronnen; ");
    EXPECT_EQ(l.heading(LessonRole::Goals), "Leerdoelen");
    EXPECT_EQ(l.heading(LessonRole::Notes), "Aantekeningen voor de docent") << "a section it lacks: the language's word";
    const Lesson en = parseLesson(kGood, "lessons/t.md", kRoot);
    EXPECT_EQ(en.language, "en");
    EXPECT_EQ(en.steps[0].heading, "Step 1: Look");
    EXPECT_EQ(en.heading(LessonRole::Questions), "Questions");
    EXPECT_EQ(en.heading(LessonRole::Notes), "Teacher's notes");
    EXPECT_EQ(parseLesson(replaced(kGood, "Scene: scenes/default.json\n", "Scene: scenes/default.json\n\nLanguage: en\n"), "lessons/t.md", kRoot)
                  .language,
              "en");
}

TEST(Lesson, MarkerMistakesNameFileAndLineAndListTheMarkers) {
    const std::string markers = "; end a '## ' heading in one of {#goals}, {#step}, {#step .optional}, {#questions}, "
                                "{#exercise}, {#code}, {#further}, {#notes}, {#sources}";
    const std::string write = " (write {#ROLE}, or {#step .optional})" + markers;
    const std::string once = " (only a step takes '.optional', once)" + markers;
    // Each mistake: the text replaced in kGood, what replaces it, the message.
    const std::tuple<std::string, std::string, std::string> mistakes[] = {
        {"## Questions {#questions}", "## Questions", "29: error: the heading 'Questions' has no role marker" + markers},
        {"## Step 2: Change {#step}", "## Step 2: Change (optional)",
         "22: error: the heading 'Step 2: Change (optional)' has no role marker" + markers},
        {"{#questions}", "{#quiz}", "29: error: unknown role '#quiz' in '{#quiz}'" + markers},
        {"{#questions}", "{questions}", "29: error: malformed marker '{questions}'" + write},
        {"{#questions}", "{#questions", "29: error: malformed marker '{#questions'" + write},
        {"{#questions}", "{ }", "29: error: malformed marker '{ }'" + write},
        {"{#questions}", "{#questions .optional}", "29: error: unknown class '.optional' in '{#questions .optional}'" + once},
        {"Change {#step}", "Change {#step .hidden}", "22: error: unknown class '.hidden' in '{#step .hidden}'" + once},
        {"## Questions {#questions}", "## {#questions}", "29: error: the marker '{#questions}' has no heading before it"},
        {"## Step 2: Change {#step}", "## Change {#step}",
         "22: error: a step heading is 'WORD N: TITLE' (Step 2: ..., Stap 2: ...), not 'Change'"},
        {"## Exercise {#exercise}", "## Exercise {#questions}", "35: error: a second {#questions} section (the first is on line 29)"},
        {"# Lesson 0: A test", "# Lesson 0: A test {#goals}", "1: error: the '# ' title takes no marker; '## ' sections do"},
        // English words with another marker are what the marker says: here a step without its number.
        {"## Questions {#questions}", "## Questions {#step}",
         "29: error: a step heading is 'WORD N: TITLE' (Step 3: ..., Stap 3: ...), not 'Questions'"},
        {"Scene: scenes/default.json\n", "Scene: scenes/default.json\n\nLanguage: fr\n", "5: error: 'Language:' is one of en, nl"},
        {"Scene: scenes/default.json\n", "Scene: scenes/default.json\n\nLanguage: nl\n\nLanguage: nl\n",
         "7: error: a second 'Language:' line"},
    };
    for (const auto& [from, to, message] : mistakes) EXPECT_EQ(errorOf(replaced(kGood, from, to)), "lessons/t.md:" + message) << to;
    // `###` headings inside a section are free.
    EXPECT_EQ(parseLesson(replaced(kGood, "Do it.", "### A part\n\nDo it."), "lessons/t.md", kRoot).exercise, "### A part\n\nDo it.");
}

TEST(Lesson, RootOfAnEditionIsTheFolderAboveLessons) {
    EXPECT_EQ(lessonRoot("/r/lessons/03-x.md"), fs::path("/r"));
    EXPECT_EQ(lessonRoot("/r/lessons/nl/03-x.md"), fs::path("/r"));
    EXPECT_EQ(lessonRoot("/r/mine/03-x.md"), fs::path("/r")) << "a folder not named lessons: the folder above";
    EXPECT_EQ(lessonRoot("/r/mine/nl/03-x.md"), fs::path("/r/mine"));
    EXPECT_EQ(lessonRoot("/r/lessons/mine/03-x.md"), fs::path("/r/lessons")) << "only a language's folder is an edition";
    EXPECT_EQ(lessonRoot("/lessons/lessons/03-x.md"), fs::path("/lessons"));
}
