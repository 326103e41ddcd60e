// The lessons' pictures (lessons/pictures/): every lesson shows one that exists, and every picture
// is written by lessons/pictures/make.sh, so none goes stale without the script that remakes it.
#include "lesson/lesson.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kLessons = fs::path(RAYLAB_SOURCE_DIR) / "lessons";
const fs::path kPictures = kLessons / "pictures";

// The pictures make.sh writes: each output is named "$here/NAME.png".
std::set<std::string> madeByScript() {
    std::ifstream in(kPictures / "make.sh");
    std::stringstream s;
    s << in.rdbuf();
    const std::string script = s.str();
    static const std::regex output(R"re("\$here/([A-Za-z0-9._-]+\.png)")re");
    std::set<std::string> names;
    for (auto it = std::sregex_iterator(script.begin(), script.end(), output); it != std::sregex_iterator(); ++it)
        names.insert((*it)[1].str());
    return names;
}

} // namespace

TEST(LessonPictures, EveryLessonShowsAPictureThatExists) {
    const auto lessons = loadLessons(kLessons);
    ASSERT_GE(lessons.size(), 12u);
    for (const Lesson& lesson : lessons) {
        SCOPED_TRACE(lesson.file.string());
        EXPECT_FALSE(lesson.pictures.empty()) << "no picture (![alt](pictures/NAME.png))";
        for (const LessonPicture& p : lesson.pictures) {
            const fs::path file = lesson.picturePath(p.source);
            EXPECT_TRUE(fs::is_regular_file(file)) << "line " << p.line << ": " << file;
            EXPECT_EQ(file.parent_path(), kPictures.lexically_normal()) << "line " << p.line << ": pictures live in lessons/pictures";
        }
    }
}

TEST(LessonPictures, EveryPictureIsMadeByTheScriptAndShownBySomeLesson) {
    const std::set<std::string> made = madeByScript();
    EXPECT_GE(made.size(), 12u);
    std::set<std::string> present;
    for (const auto& e : fs::directory_iterator(kPictures))
        if (e.path().extension() == ".png") present.insert(e.path().filename().string());
    EXPECT_EQ(present, made) << "a PNG in lessons/pictures that make.sh does not write, or one it writes that is missing";
    std::set<std::string> shown;
    for (const Lesson& lesson : loadLessons(kLessons))
        for (const LessonPicture& p : lesson.pictures) shown.insert(lesson.picturePath(p.source).filename().string());
    for (const std::string& name : made) {
        EXPECT_TRUE(shown.count(name)) << name << " is made but no lesson shows it";
        const auto bytes = fs::exists(kPictures / name) ? fs::file_size(kPictures / name) : 0;
        EXPECT_LE(bytes, 100u * 1024u) << name << ": keep committed pictures small";
    }
}
