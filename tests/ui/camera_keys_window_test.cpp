// The camera keys through the real `raylab` window under Xvfb (tests/ui/viewer_run.h): the
// script's `key NAME FRAMES` holds W S A D Q E and the four arrows as a user holds them over the
// viewport, and each must move or turn the camera its own way, read back from the scene saved
// before and after it. One viewer run. Skips (with the reason) only where Xvfb is not installed.
#include "ui/viewer_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace raylab::ui {
namespace {

using namespace test_run;

const std::string kScene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json";

struct SavedCamera {
    glm::vec3 position{0.0f}, lookAt{0.0f}, up{0.0f};
    glm::vec3 forward() const { return glm::normalize(lookAt - position); }
};

SavedCamera savedCamera(const fs::path& file) {
    std::ifstream in(file);
    const nlohmann::json j = nlohmann::json::parse(in);
    auto vec = [&](const char* key) {
        const nlohmann::json& v = j.at("camera").at(key);
        return glm::vec3(v.at(0).get<float>(), v.at(1).get<float>(), v.at(2).get<float>());
    };
    return {vec("position"), vec("look_at"), vec("up")};
}

// What a key does, in the camera's frame before it: a move along an axis (sign +1 or −1 along
// forward, right or up) keeps the view direction; a turn keeps the eye and tilts the direction
// towards right or up.
enum class Axis { Forward, Right, Up };
struct KeyEffect {
    const char* name;
    bool turn;
    Axis axis;
    float sign;
};

constexpr KeyEffect kEffects[] = {
    {"w", false, Axis::Forward, 1},  {"s", false, Axis::Forward, -1}, {"d", false, Axis::Right, 1},
    {"a", false, Axis::Right, -1},   {"e", false, Axis::Up, 1},       {"q", false, Axis::Up, -1},
    {"right", true, Axis::Right, 1}, {"left", true, Axis::Right, -1}, {"up", true, Axis::Up, 1},
    {"down", true, Axis::Up, -1},
};

TEST(ViewerCameraKeysWindow, EachKeyMovesOrTurnsTheCameraItsOwnWay) {
    RAYLAB_START_XVFB(x);
    const fs::path dir = test::windowTestDir("raylab_camera_keys_");
    const std::string d = dir.string();
    std::string script = "save " + d + "/start.json\n";
    for (const KeyEffect& k : kEffects) script += std::string("key ") + k.name + " 3\nsave " + d + "/" + k.name + ".json\n";
    script += "quit\n";
    ViewerOptions small;
    small.scale = 0.25f;
    const ViewerRun run = runViewer(x, dir, script, kScene, small);
    ASSERT_EQ(run.status, 0) << run.log;

    SavedCamera before = savedCamera(dir / "start.json");
    for (const KeyEffect& k : kEffects) {
        SCOPED_TRACE(k.name);
        const SavedCamera after = savedCamera(dir / (std::string(k.name) + ".json"));
        const glm::vec3 f = before.forward(), r = glm::normalize(glm::cross(f, before.up)), u = glm::normalize(before.up);
        const glm::vec3 axis = k.axis == Axis::Forward ? f : k.axis == Axis::Right ? r : u;
        const glm::vec3 move = after.position - before.position;
        const float scale = std::max(1.0f, glm::length(before.position));
        if (k.turn) {
            // The eye stays; the direction leans towards the axis and not towards the other one.
            EXPECT_LT(glm::length(move), 1e-5f * scale);
            const glm::vec3 g = after.forward();
            const glm::vec3 other = k.axis == Axis::Right ? u : r;
            const float lean = k.axis == Axis::Right ? glm::dot(g, r) : glm::dot(g, u) - glm::dot(f, u);
            EXPECT_GT(k.sign * lean, 1e-3f) << "turned the wrong way or not at all";
            const float drift = k.axis == Axis::Right ? glm::dot(g, other) - glm::dot(f, other) : glm::dot(g, other);
            EXPECT_LT(std::abs(drift), 1e-4f);
        } else {
            // The eye moves along the axis, the look-at with it: the direction stays.
            EXPECT_GT(k.sign * glm::dot(move, axis), 1e-3f) << "moved the wrong way or not at all";
            EXPECT_GT(k.sign * glm::dot(move, axis), 0.999f * glm::length(move)) << "moved off the axis";
            EXPECT_LT(glm::length(after.forward() - f), 1e-4f);
        }
        EXPECT_EQ(after.up, before.up);
        before = after;
    }
    EXPECT_EQ(run.log.find("error"), std::string::npos) << run.log;
    std::error_code ec;
    fs::remove_all(dir, ec);
}

} // namespace
} // namespace raylab::ui
