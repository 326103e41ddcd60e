// The lessons' `inspect X Y` and `explore K` steps work on the scene the step has open: the pixel
// lies in the image, the inspector records paths there, and an `explore K` finds a surface at
// bounce K of the first path (the viewer would otherwise report the step's command as failed).
#include "inspect/path_inspector.h"
#include "lesson/lesson.h"
#include "scene/scene_loader.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

namespace raylab::test {
namespace {

using LessonInspectTest = GlTest;

TEST_F(LessonInspectTest, EveryInspectAndExploreStepRecordsPathsOnItsScene) {
    int inspects = 0, explores = 0;
    for (const Lesson& lesson : loadLessons(std::filesystem::path(RAYLAB_SOURCE_DIR) / "lessons")) {
        for (const LessonStep& step : lesson.steps) {
            std::filesystem::path scene = lesson.scenePath;
            std::vector<std::string> sets;
            std::vector<PathRecord> paths;
            for (const ScriptCommand& c : step.commands) {
                const std::string where = lesson.file.filename().string() + ":" + std::to_string(c.line);
                if (c.name == "open") {
                    scene = lesson.resolve(c.args[0]);
                    sets.clear();
                } else if (c.name == "set") {
                    sets.push_back(c.args[0] + "=" + c.args[1]);
                } else if (c.name == "inspect") {
                    const Scene s = loadScene(scene, sets);
                    const int x = std::stoi(c.args[0]), y = std::stoi(c.args[1]);
                    ASSERT_LT(x, s.render.width) << where;
                    ASSERT_LT(y, s.render.height) << where;
                    PathInspector inspector;
                    inspector.setScene(s);
                    paths = inspector.record(x, y, c.args.size() > 2 ? std::stoi(c.args[2]) : 8);
                    ASSERT_FALSE(paths.empty()) << where;
                    ++inspects;
                } else if (c.name == "explore") {
                    const std::size_t k = std::stoul(c.args[0]), p = c.args.size() > 1 ? std::stoul(c.args[1]) : 0;
                    ASSERT_LT(p, paths.size()) << where << ": explore needs an inspect before it in the step";
                    ASSERT_LT(k, paths[p].bounces.size()) << where;
                    EXPECT_TRUE(paths[p].bounces[k].hit) << where << ": bounce " << k << " is the sky";
                    ++explores;
                }
            }
        }
    }
    EXPECT_GE(inspects, 3);
    EXPECT_GE(explores, 1);
}

} // namespace
} // namespace raylab::test
