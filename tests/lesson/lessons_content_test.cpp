// The shipped lessons (lessons/*.md): every lesson loads, its scene loads, every step's commands
// parse, and every `set KEY VALUE` of a step applies to the scene the step has open through the
// loader's --set mechanism (loadScene(scene, {"KEY=VALUE", ...}), the earlier sets of the step
// included, as the viewer would apply them). Scenes a step opens must load too.
#include "lesson/lesson.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kLessons = fs::path(RAYLAB_SOURCE_DIR) / "lessons";

// Scenes and keys the lessons use that exist only on other branches, so the checks above must fail
// for them on this branch. `what` is a scene path (as `open` gives it) or a `set` key, where `*`
// stands for one dotted part (a material name, an object index). A step that opens a listed scene
// cannot have its later commands checked here: they are covered by that scene's entry.
// Each entry must still fail here (an entry that starts to apply is reported, so the list stays
// exact) and each must be used by some lesson.
// remove when issue-materials / issue-geometry are merged
struct NeedsOtherBranch {
    const char* lesson;   // file name in lessons/
    const char* what;     // scene path or key pattern
    const char* branch;   // the branch that brings it
};
const std::vector<NeedsOtherBranch> kNeedsOtherBranches = {
};

bool keyMatches(const std::string& pattern, const std::string& key) {
    std::istringstream p(pattern), k(key);
    std::string a, b;
    while (true) {
        const bool morePattern = bool(std::getline(p, a, '.'));
        const bool moreKey = bool(std::getline(k, b, '.'));
        if (!morePattern || !moreKey) return morePattern == moreKey;
        if (a != "*" && a != b) return false;
    }
}

// Index into kNeedsOtherBranches, or -1.
int allowListed(const std::string& lesson, const std::string& what) {
    for (size_t i = 0; i < kNeedsOtherBranches.size(); ++i) {
        const auto& e = kNeedsOtherBranches[i];
        if (e.lesson == lesson && (e.what == what || keyMatches(e.what, what))) return int(i);
    }
    return -1;
}

std::string loadError(const fs::path& scene, const std::vector<std::string>& overrides) {
    try {
        loadScene(scene, overrides);
    } catch (const SceneError& e) {
        return e.what();
    }
    return {};
}

// Number of entries in the scene file's "objects" array (meshes included, whatever the branch).
size_t objectCount(const fs::path& scene) {
    std::ifstream in(scene);
    const auto doc = nlohmann::json::parse(in, nullptr, true, /*ignore_comments=*/true);
    return doc.contains("objects") ? doc["objects"].size() : 0;
}

std::string where(const Lesson& l, const ScriptCommand& c) {
    return l.file.filename().string() + ":" + std::to_string(c.line) + ": " + c.name;
}

// Runs every step of `lesson` against the scene loader; records which allow-list entries it used.
void checkSteps(const Lesson& lesson, std::set<int>& used) {
    const std::string name = lesson.file.filename().string();
    for (const LessonStep& step : lesson.steps) {
        fs::path scene = lesson.scenePath;   // a step starts on the lesson's scene
        bool elsewhere = false;              // the step opened an allow-listed scene
        std::vector<std::string> overrides;
        for (ScriptCommand c : step.commands) {
            const std::string at = where(lesson, c);
            if (c.name == "stage") c = ScriptCommand{c.line, "set", {"render.stage", c.args[0]}};   // its meaning
            if ((c.name == "split-a" || c.name == "split-b") && !elsewhere) {
                // A side's override applies to the step's scene as it stands (the split screen checks it).
                std::vector<std::string> with = overrides;
                with.push_back(c.args[0] + "=" + c.args[1]);
                EXPECT_EQ(loadError(scene, with), "") << at << ": " << c.args[0] << " " << c.args[1];
                continue;
            }
            if (c.name == "open") {
                const fs::path path = lesson.resolve(c.args[0]);
                const std::string error = fs::exists(path) ? loadError(path, {}) : "missing";
                overrides.clear();
                if (const int i = allowListed(name, c.args[0]); i >= 0) {
                    used.insert(i);
                    EXPECT_FALSE(error.empty()) << at << ": " << c.args[0] << " now loads on this branch: remove it "
                                                << "from kNeedsOtherBranches";
                    elsewhere = true;
                    continue;
                }
                EXPECT_EQ(error, "") << at << ": " << c.args[0];
                scene = path;
                elsewhere = !error.empty();   // reported once; its later commands are not checked
            } else if (c.name == "set") {
                const std::string& key = c.args[0];
                EXPECT_NE(key.rfind("selected.", 0), 0u) << at << ": lessons use full keys, not selected.*";
                if (elsewhere) continue;
                std::vector<std::string> with = overrides;
                with.push_back(key + "=" + c.args[1]);
                const std::string error = loadError(scene, with);
                if (const int i = allowListed(name, key); i >= 0) {
                    used.insert(i);
                    EXPECT_FALSE(error.empty()) << at << ": " << key << " now applies on this branch: remove it from "
                                                << "kNeedsOtherBranches";
                } else {
                    EXPECT_EQ(error, "") << at << ": " << key << " " << c.args[1];
                    if (error.empty()) overrides = std::move(with);   // a failed set is not kept
                }
            } else if (c.name == "select") {
                if (elsewhere) continue;
                const double n = std::stod(c.args[0]);
                EXPECT_TRUE(n >= 0 && n < double(objectCount(scene)) && n == double(size_t(n)))
                    << at << ": no object " << c.args[0] << " in " << scene;
            } else if (c.name == "scale") {
                const double v = std::stod(c.args[0]);
                EXPECT_TRUE(v >= 0.125 && v <= 2) << at << ": scale is 0.125 to 2";
            } else {
                // A lesson step sets state; it never ends the viewer or writes files.
                for (const char* banned : {"quit", "screenshot", "export", "save", "window", "click", "ui-scale", "key",
                                           "lesson", "lesson-step", "self-test", "teach"})
                    EXPECT_NE(c.name, banned) << at << ": not for lessons";
            }
        }
    }
}

std::vector<std::string> lessonFileNames() {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(kLessons))
        if (e.path().extension() == ".md" && e.path().filename() != "README.md")
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class ShippedLesson : public testing::TestWithParam<std::string> {};

std::string testName(const testing::TestParamInfo<std::string>& info) {
    std::string n = info.param.substr(0, info.param.size() - 3);
    for (char& ch : n)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return n;
}

} // namespace

// Twelve lessons in the order of issue 6, loadLessons gives them in file-name order.
TEST(Lessons, AllTwelveLoadInOrder) {
    const std::vector<Lesson> lessons = loadLessons(kLessons);
    ASSERT_EQ(lessons.size(), 12u);
    for (size_t i = 0; i < lessons.size(); ++i) {
        const std::string prefix = (i + 1 < 10 ? "0" : "") + std::to_string(i + 1) + "-";
        EXPECT_EQ(lessons[i].file.filename().string().rfind(prefix, 0), 0u) << lessons[i].file;
    }
}

TEST_P(ShippedLesson, LoadsWithItsSceneAndEveryStepApplies) {
    const Lesson lesson = loadLesson(kLessons / GetParam());
    EXPECT_FALSE(lesson.title.empty());
    EXPECT_GE(lesson.goals.size(), 2u);
    EXPECT_GE(lesson.steps.size(), 3u);
    EXPECT_LE(lesson.steps.size(), 6u);
    EXPECT_GE(lesson.questions.size(), 3u);
    EXPECT_FALSE(lesson.exercise.empty());
    EXPECT_FALSE(lesson.sources.empty()) << "a lesson cites its sources";
    EXPECT_EQ(loadError(lesson.scenePath, {}), "");
    for (const LessonStep& step : lesson.steps) {
        EXPECT_FALSE(step.text.empty()) << GetParam() << ":" << step.line << ": step without text";
        // Steps can be taken in any order (presenter keys jump), so each starts by opening a scene.
        ASSERT_FALSE(step.commands.empty());
        EXPECT_EQ(step.commands.front().name, "open") << GetParam() << ":" << step.line;
    }
    std::set<int> used;
    checkSteps(lesson, used);
}

INSTANTIATE_TEST_SUITE_P(Lessons, ShippedLesson, testing::ValuesIn(lessonFileNames()), testName);

// Every entry of kNeedsOtherBranches is used by the lesson it names (no stale entries).
TEST(Lessons, AllowListHasNoStaleEntries) {
    std::set<int> used;
    for (const Lesson& lesson : loadLessons(kLessons)) checkSteps(lesson, used);
    for (size_t i = 0; i < kNeedsOtherBranches.size(); ++i)
        EXPECT_TRUE(used.count(int(i))) << kNeedsOtherBranches[i].lesson << " does not use "
                                        << kNeedsOtherBranches[i].what << " (listed for "
                                        << kNeedsOtherBranches[i].branch << ")";
}

TEST(Lessons, AllowListPatternsMatchWholeParts) {
    EXPECT_TRUE(keyMatches("materials.*.roughness", "materials.ball.roughness"));
    EXPECT_FALSE(keyMatches("materials.*.roughness", "materials.ball.albedo"));
    EXPECT_FALSE(keyMatches("materials.*.roughness", "materials.roughness"));
    EXPECT_FALSE(keyMatches("render.nee", "render.nee.x"));
    EXPECT_TRUE(keyMatches("render.nee", "render.nee"));
}
