// The Dutch edition (lessons/nl/) against the English lessons: a Dutch lesson resolves its root,
// scene and pictures like its original; the drift check (lesson/lesson_edition.h) finds every kind
// of drift in a fixture edition; and every shipped English lesson has a Dutch twin that does not
// drift, and every Dutch lesson an English one.
#include "lesson/lesson.h"
#include "lesson/lesson_edition.h"

#include "support/dutch_lesson_fixture.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kLessons = fs::path(RAYLAB_SOURCE_DIR) / "lessons";

std::vector<std::string> lessonNames(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.path().extension() == ".md" && e.path().filename() != "README.md") names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const std::string& l : lines) s += l + "\n";
    return s;
}

std::string replacedOnce(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

class LessonEditions : public testing::Test {
protected:
    void SetUp() override { f = test::makeDutchLessonFixture(dir, "03-ray-sphere.md"); }
    void TearDown() override { fs::remove_all(dir); }
    const fs::path dir = fs::temp_directory_path() / ("raylab_lesson_editions_" + std::to_string(::getpid()));
    test::DutchLessonFixture f;
};

} // namespace

TEST_F(LessonEditions, ADutchLessonResolvesLikeItsOriginal) {
    const Lesson en = loadLesson(f.english), nl = loadLesson(f.dutch);
    EXPECT_EQ(nl.language, "nl");
    EXPECT_EQ(en.language, "en");
    EXPECT_EQ(lessonRoot(f.dutch), lessonRoot(f.english));
    EXPECT_EQ(nl.root, en.root);
    EXPECT_EQ(nl.root, fs::absolute(dir).lexically_normal());
    EXPECT_EQ(nl.scenePath, en.scenePath);
    EXPECT_TRUE(fs::is_regular_file(nl.scenePath));
    ASSERT_FALSE(nl.pictures.empty());
    EXPECT_EQ(nl.pictures[0].source.rfind("../pictures/", 0), 0u);
    for (std::size_t i = 0; i < nl.pictures.size(); ++i) {
        EXPECT_EQ(nl.picturePath(nl.pictures[i].source), en.picturePath(en.pictures[i].source));
        EXPECT_TRUE(fs::is_regular_file(nl.picturePath(nl.pictures[i].source))) << nl.picturePath(nl.pictures[i].source);
    }
    EXPECT_EQ(nl.heading(LessonRole::Goals), "Leerdoelen");
    EXPECT_EQ(nl.steps[0].heading.rfind("Stap 1: ", 0), 0u) << nl.steps[0].heading;
    EXPECT_EQ(nl.steps[0].title, en.steps[0].title);
    // Each edition finds the other; a file in no lessons folder has none.
    EXPECT_EQ(lessonInLanguage(f.english, "nl"), fs::absolute(f.dutch).lexically_normal());
    EXPECT_EQ(lessonInLanguage(f.dutch, "en"), fs::absolute(f.english).lexically_normal());
    EXPECT_EQ(lessonInLanguage(f.dutch, "nl"), fs::absolute(f.dutch).lexically_normal());
    EXPECT_EQ(lessonInLanguage(dir / "elsewhere" / "x.md", "nl"), std::nullopt);
    EXPECT_EQ(lessonEditionFolder(kLessons, "nl"), kLessons / "nl");
    EXPECT_EQ(lessonEditionFolder(kLessons, "en"), kLessons);
}

TEST_F(LessonEditions, TheFixtureDoesNotDriftAndEveryKindOfDriftIsFound) {
    EXPECT_EQ(joined(editionDifferences(loadLesson(f.english), loadLesson(f.dutch))), "");
    // The test can fail: each change of the Dutch text is a drift, named in the Dutch file. Each
    // is the Dutch text replaced, what replaces it, and a part of the message.
    const std::tuple<std::string, std::string, std::string> drifts[] = {
        {"debug-view depth\nwait-spp 4", "debug-view normals\nwait-spp 4", "step 1's 'debug-view normals'"},
        {"wait-spp 4\nexpect debug-view depth", "wait-spp 4\nhold\nexpect debug-view depth", "step 1's"},
        {"Language: nl", "Language: en", "'Language: en' is the original's language"},
        {"Minutes: 45", "Minutes: 50", "'Minutes: 50' differs"},
        {"Scene: scenes/lesson_one_sphere.json", "Scene: scenes/default.json", "'Scene: scenes/default.json' differs"},
        {"](../pictures/03-ray-sphere.png)", "](../pictures/05-slab-test.png)", "picture 1"},
        {"Normals {#step}", "Normals {#step .optional}", "step 2 (optional) differs"},
        {"## Vragen {#questions}\n\n1. ", "## Vragen {#questions}\n\n1. An extra question.\n2. ", "questions differs"},
        {"## Bronnen {#sources}", "## Bronnen {#further}", "the sections ("},
    };
    const std::string edition = test::readLessonText(f.dutch);
    for (const auto& [from, to, part] : drifts) {
        std::ofstream(f.dutch, std::ios::binary) << replacedOnce(edition, from, to);
        const std::string drift = joined(editionDifferences(loadLesson(f.english), loadLesson(f.dutch)));
        EXPECT_EQ(drift.rfind(f.dutch.string() + ":", 0), 0u) << to << ": " << drift;
        EXPECT_NE(drift.find(part), std::string::npos) << to << ": " << drift;
    }
}

// The real folders: until every translation is in, this names each missing Dutch lesson.
TEST(LessonEditionsShipped, EveryEnglishLessonHasADutchTwinThatDoesNotDrift) {
    const std::vector<std::string> english = lessonNames(kLessons);
    ASSERT_GE(english.size(), 18u);
    for (const std::string& name : english) {
        SCOPED_TRACE(name);
        const fs::path dutch = kLessons / "nl" / name;
        if (!fs::is_regular_file(dutch)) {
            ADD_FAILURE() << dutch << " is missing: every English lesson has its Dutch edition under the same name";
            continue;
        }
        const Lesson en = loadLesson(kLessons / name), nl = loadLesson(dutch);
        EXPECT_EQ(nl.language, "nl") << dutch << ": no 'Language: nl' line";
        EXPECT_EQ(joined(editionDifferences(en, nl)), "");
        for (const LessonPicture& p : nl.pictures)
            EXPECT_TRUE(fs::is_regular_file(nl.picturePath(p.source))) << dutch << ":" << p.line << ": " << p.source;
    }
    for (const std::string& name : lessonNames(kLessons / "nl"))
        EXPECT_TRUE(fs::is_regular_file(kLessons / name)) << "lessons/nl/" << name << " has no English twin lessons/" << name;
    EXPECT_TRUE(fs::is_regular_file(kLessons / "nl" / "README.md")) << "the Dutch index and glossary";
}
