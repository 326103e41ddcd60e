// `expect` (script/expectation.h): a scene key or the view state holds its value, or the failure
// says what it is instead.
#include "script/expectation.h"

#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace raylab;

namespace {

const std::filesystem::path kScene = std::filesystem::path(RAYLAB_SOURCE_DIR) / "scenes/lesson_one_sphere.json";

} // namespace

TEST(Expectation, SceneKeysCompareByValue) {
    const Scene s = loadScene(kScene, {"render.max_bounces=1", "materials.ball.albedo=[0.9, 0.15, 0.1]"});
    const ViewState view;
    EXPECT_EQ(expectationFailure(s, view, "render.max_bounces", "1"), "");
    EXPECT_EQ(expectationFailure(s, view, "render.max_bounces", "8"), "render.max_bounces is 1, expected 8");
    EXPECT_EQ(expectationFailure(s, view, "materials.ball.albedo", "[0.9, 0.15, 0.1]"), "");   // floats as stored
    EXPECT_EQ(expectationFailure(s, view, "materials.ball.albedo", "[0.9, 0.15, 0.2]"),
              "materials.ball.albedo is [0.9, 0.15, 0.1], expected [0.9, 0.15, 0.2]");
    EXPECT_EQ(expectationFailure(s, view, "objects.1.radius", "1"), "");
    EXPECT_EQ(expectationFailure(s, view, "render.tone_map", "aces"), "");
    EXPECT_EQ(expectationFailure(s, view, "render.tone_map", "clamp"), "render.tone_map is aces, expected clamp");
    EXPECT_EQ(expectationFailure(s, view, "render.nee", "false"), expectationFailure(loadScene(kScene), view, "render.nee", "false"));
    EXPECT_NE(expectationFailure(s, view, "render.max_bounce", "1").find("unknown key"), std::string::npos);
    EXPECT_NE(expectationFailure(s, view, "render.max_bounces", "many"), "");
    EXPECT_NE(expectationFailure(s, view, "materials.ball.albedo_texture", "x.png").find("file or a name"), std::string::npos);
}

TEST(Expectation, ViewStateComparesWhatTheStepSet) {
    const Scene s = loadScene(kScene);
    ViewState view;
    EXPECT_EQ(expectationFailure(s, view, "debug-view", "beauty"), "");
    EXPECT_EQ(expectationFailure(s, view, "debug-view", "noise"), "the debug view is beauty, expected noise");
    EXPECT_EQ(expectationFailure(s, view, "scale", "1"), "the resolution scale is not known here (set it with scale S first)");
    view.scale = 0.5;
    view.bounceStep = 2;
    EXPECT_EQ(expectationFailure(s, view, "scale", "0.5"), "");
    EXPECT_EQ(expectationFailure(s, view, "scale", "1"), "the resolution scale is 0.5, expected 1");
    EXPECT_EQ(expectationFailure(s, view, "bounce-step", "2"), "");
    EXPECT_EQ(expectationFailure(s, view, "bounce-step", "off"), "bounce stepping is at 2, expected off");
}
