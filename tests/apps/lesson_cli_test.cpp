// raylab-lesson as a teacher runs it: a handout by the lesson's name, the Dutch edition's with
// --lang nl, and located errors with a non-zero exit for an unknown lesson or language, an output
// it cannot write and bad flags.
#include "support/dutch_lesson_fixture.h"
#include "support/render_cli.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace raylab::test;
namespace fs = std::filesystem;

namespace {

// Runs in the source folder: outputs are named by absolute paths into `dir`.
CliRun lessonCli(const std::string& args, const fs::path& dir) { return runProgram(RAYLAB_LESSON_EXE, args, dir); }

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

} // namespace

TEST(LessonCli, ExportsBothSheetsOfALessonByName) {
    const fs::path dir = scratchDir("raylab_lesson_export");
    CliRun r = lessonCli("export 03 --pupil -o " + quoted(dir / "pupil.html"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string pupil = slurp(dir / "pupil.html");
    EXPECT_NE(pupil.find("<h1>Lesson 3: Ray–sphere intersection</h1>"), std::string::npos);
    EXPECT_EQ(pupil.find("Teacher's notes"), std::string::npos);
    r = lessonCli("export '" + (fs::path(RAYLAB_SOURCE_DIR) / "lessons/03-ray-sphere.md").string() + "' --teacher -o " + quoted(dir / "teacher.html"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "teacher.html").find("Teacher's notes and answers"), std::string::npos);
    r = lessonCli("list", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("03-ray-sphere\tVWO 5–6\t45\tLesson 3: Ray–sphere intersection"), std::string::npos) << r.out;
    fs::remove_all(dir);
}

TEST(LessonCli, BadInputExitsNonZeroWithALocatedMessage) {
    const fs::path dir = scratchDir("raylab_lesson_bad");
    CliRun r = lessonCli("export 99-nothing --pupil -o " + quoted(dir / "a.html"), dir);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("99-nothing: error: no such lesson file, nor a lesson of that name"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("03-ray-sphere"), std::string::npos) << "the message lists the lessons: " << r.err;
    r = lessonCli("export 03 --pupil -o '" + (dir / "no/such/folder/a.html").string() + "'", dir);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find((dir / "no/such/folder/a.html").string() + ": error: cannot write the sheet"), std::string::npos) << r.err;
    r = lessonCli("export 03 -o " + quoted(dir / "a.html"), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("error: give one of --pupil or --teacher"), std::string::npos) << r.err;
    r = lessonCli("export 03 --pupil --teacher -o " + quoted(dir / "a.html"), dir);
    EXPECT_EQ(r.status, 2);
    r = lessonCli("export 03 --pupil -o " + quoted(dir / "a.pdf"), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find((dir / "a.pdf").string() + ": error: the sheet is HTML"), std::string::npos) << r.err;
    r = lessonCli("export 03 --pupil --colour -o " + quoted(dir / "a.html"), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_FALSE(fs::exists(dir / "a.html"));
    fs::remove_all(dir);
}

TEST(LessonCli, LangNlExportsTheDutchEditionsSheets) {
    const fs::path dir = scratchDir("raylab_lesson_dutch");
    const DutchLessonFixture f = makeDutchLessonFixture(dir / "repo", "03-ray-sphere.md");
    // The English file named, --lang nl: its Dutch twin's sheets.
    CliRun r = lessonCli("export " + quoted(f.english) + " --lang nl --pupil -o " + quoted(dir / "pupil.html"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string pupil = slurp(dir / "pupil.html");
    EXPECT_NE(pupil.find("<h1>Les 3: Ray–sphere intersection</h1>"), std::string::npos) << pupil.substr(0, 2000);
    EXPECT_NE(pupil.find("<html lang=\"nl\">"), std::string::npos);
    EXPECT_NE(pupil.find("<h2>Leerdoelen</h2>"), std::string::npos);
    EXPECT_EQ(pupil.find("Aantekeningen voor de docent"), std::string::npos) << "the pupil's sheet has no notes";
    r = lessonCli("export " + quoted(f.english) + " --lang nl --teacher -o " + quoted(dir / "teacher.html"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "teacher.html").find("Aantekeningen voor de docent en antwoorden"), std::string::npos);
    // Without --lang a file is taken as it is.
    r = lessonCli("export " + quoted(f.dutch) + " --pupil -o " + quoted(dir / "as-is.html"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "as-is.html").find("<h1>Les 3:"), std::string::npos);
    r = lessonCli("export " + quoted(f.dutch) + " --lang en --pupil -o " + quoted(dir / "en.html"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "en.html").find("<h1>Lesson 3:"), std::string::npos);
    // An unknown language, and a lesson the edition lacks.
    r = lessonCli("export 03 --lang fr --pupil -o " + quoted(dir / "fr.html"), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--lang: unknown language 'fr' (en, nl)"), std::string::npos) << r.err;
    r = lessonCli("list --lang xx", dir);
    EXPECT_EQ(r.status, 2);
    fs::remove(f.dutch);
    r = lessonCli("export " + quoted(f.english) + " --lang nl --pupil -o " + quoted(dir / "gone.html"), dir);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find(f.dutch.string() + ": error: cannot read the lesson"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "fr.html"));
    fs::remove_all(dir);
}
