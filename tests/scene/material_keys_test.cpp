// The material keys (roughness, f0, transmission, ior) and the light-sampling switches
// (render.nee, render.mis) load, validate and round-trip.
#include "scene/parameters.h"
#include "scene/scene_loader.h"

#include "support/scene_errors.h"

#include <gtest/gtest.h>

#include <string>

using namespace raylab;

namespace {

std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
    return test::sceneErrorOf(text, overrides, "m.json", "");
}

} // namespace

TEST(SceneMaterialKeys, DefaultsAreExactlyLambertian) {
    const Material m;
    EXPECT_EQ(m.f0, glm::vec3(0.0f));
    EXPECT_EQ(m.transmission, 0.0f);
    EXPECT_EQ(m.roughness, 1.0f);
    EXPECT_EQ(m.ior, 1.5f);
    const Scene s;   // the best estimator: NEE with MIS (bench/samplers.md)
    EXPECT_TRUE(s.render.nee);
    EXPECT_TRUE(s.render.mis);
}

TEST(SceneMaterialKeys, LoadScalarAndRgbF0AndTheRest) {
    const Scene s = parseScene(R"({
      "materials": { "gold": { "albedo": 0, "f0": [1, 0.71, 0.29], "roughness": 0.3 },
                     "glass": { "transmission": 1, "ior": 1.33, "f0": 0.04 } },
      "objects": [ { "material": "gold" }, { "material": "glass" } ] })",
                               "m.json");
    ASSERT_EQ(s.materials.size(), 2u);
    const Material& glass = s.materials[0];   // sorted by name
    const Material& gold = s.materials[1];
    EXPECT_EQ(gold.f0, glm::vec3(1.0f, 0.71f, 0.29f));
    EXPECT_EQ(gold.roughness, 0.3f);
    EXPECT_EQ(glass.f0, glm::vec3(0.04f));
    EXPECT_EQ(glass.transmission, 1.0f);
    EXPECT_EQ(glass.ior, 1.33f);
}

TEST(SceneMaterialKeys, OutOfRangeValuesAreLocatedErrors) {
    EXPECT_EQ(errorOf(R"({ "materials": { "m": { "roughness": 1.5 } }, "objects": [ {} ] })"),
              "m.json:1:38: error: materials.m.roughness: must be in [0, 1], got 1.5");
    EXPECT_EQ(errorOf(R"({ "materials": { "m": { "ior": 0 } }, "objects": [ {} ] })"),
              "m.json:1:32: error: materials.m.ior: must be > 0, got 0");
    EXPECT_EQ(errorOf(R"({ "materials": { "m": { "f0": [1, 2, 0] } }, "objects": [ {} ] })"),
              "m.json:1:35: error: materials.m.f0[1]: must be in [0, 1], got 2");
    EXPECT_EQ(errorOf(R"({ "materials": { "m": { "transmission": -0.1 } }, "objects": [ {} ] })"),
              "m.json:1:41: error: materials.m.transmission: must be in [0, 1], got -0.1");
}

TEST(SceneMaterialKeys, NeeAndMisAreBooleansFromFileAndSet) {
    const std::string text = R"({ "render": { "nee": true, "mis": false }, "objects": [ {} ] })";
    const Scene a = parseScene(text, "m.json");
    EXPECT_TRUE(a.render.nee);
    EXPECT_FALSE(a.render.mis);
    const Scene b = parseScene(text, "m.json", {"render.nee=false", "render.mis=true"});
    EXPECT_FALSE(b.render.nee);
    EXPECT_TRUE(b.render.mis);
    EXPECT_EQ(errorOf(R"({ "render": { "nee": 1 }, "objects": [ {} ] })"),
              "m.json:1:22: error: render.nee: expected true or false, got number");
    EXPECT_EQ(errorOf(R"({ "objects": [ {} ] })", {"render.mis=yes"}),
              "--set render.mis=yes: error: render.mis: expected true or false, got string");
    // Round trip through sceneToJson keeps booleans as booleans.
    const nlohmann::json j = sceneToJson(a);
    EXPECT_TRUE(j["render"]["nee"].is_boolean());
    EXPECT_EQ(j["render"]["nee"], true);
    EXPECT_EQ(j["materials"]["default"]["f0"], nlohmann::json::array({0, 0, 0}));
}
