// The path inspector names the light a light sample picked in the tracer's numbering (emissive
// spheres, emissive triangles, then the scene's point, spot and distant lights) and shows a delta
// light's MIS density as "delta" rather than the FLOAT_MAX the estimator weighs with; the JSON and
// CSV exports carry both.
#include "inspect/light_names.h"
#include "inspect/path_export.h"
#include "inspect/path_inspector.h"
#include "scene/scene_loader.h"
#include "support/gl_test.h"
#include "../render/render_helpers.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace raylab::test {
namespace {

Light lightOf(Light::Type type, float angularRadius = 0.0f) {
    Light l;
    l.type = type;
    l.angularRadius = angularRadius;
    return l;
}

TEST(LightNaming, FollowsTheTracersNumbering) {
    const LightNumbering n{2, 3, {lightOf(Light::Type::Point), lightOf(Light::Type::Spot), lightOf(Light::Type::Distant)}};
    EXPECT_EQ(lightSampleName(n, -1), "sky");
    EXPECT_EQ(lightSampleName(n, 0), "sphere light 0");
    EXPECT_EQ(lightSampleName(n, 1), "sphere light 1");
    EXPECT_EQ(lightSampleName(n, 2), "triangle light 0");
    EXPECT_EQ(lightSampleName(n, 4), "triangle light 2");
    EXPECT_EQ(lightSampleName(n, 5), "point light 0");
    EXPECT_EQ(lightSampleName(n, 6), "spot 1");
    EXPECT_EQ(lightSampleName(n, 7), "sun 2");
    EXPECT_EQ(lightSampleName(n, 8), "light 8");
    EXPECT_EQ(sceneLight(n, 4), nullptr);
    ASSERT_NE(sceneLight(n, 6), nullptr);
    EXPECT_EQ(sceneLight(n, 6)->type, Light::Type::Spot);
}

TEST(LightNaming, DeltaLightsAreThoseNoRayCanHit) {
    EXPECT_TRUE(isDeltaLight(lightOf(Light::Type::Point)));
    EXPECT_TRUE(isDeltaLight(lightOf(Light::Type::Spot)));
    EXPECT_TRUE(isDeltaLight(lightOf(Light::Type::Distant, 0.0f)));
    EXPECT_FALSE(isDeltaLight(lightOf(Light::Type::Distant, 0.27f)));
    BounceRecord b;
    b.lightMisPdf = 0.5f;
    EXPECT_EQ(lightMisPdfText(b), "0.5");
    b.lightDelta = true;
    EXPECT_EQ(lightMisPdfText(b), "delta (never hit by BSDF rays)");
}

using LightNamingGlTest = GlTest;

// scenes/lights.json (a point light, a spot, a sun with a disc) plus one emissive sphere, so the
// scene's lights start at index 1: the floor's light samples name all three by their scene index.
TEST_F(LightNamingGlTest, TheInspectorNamesEachLightAndExportsTheDeltaDensity) {
    Scene scene = loadScene(scenePath("lights.json"));
    scene.render.width = 48;
    scene.render.height = 27;
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = glm::vec3(1.0f);
    lamp.emissionStrength = 40.0f;   // a fair share of the light choice by power
    scene.materials.push_back(lamp);
    Sphere s;
    s.center = glm::vec3(0.0f, 3.0f, -3.0f);
    s.radius = 0.2f;
    s.material = int(scene.materials.size()) - 1;
    scene.spheres.push_back(s);
    PathInspector inspector;
    inspector.setScene(scene);
    ASSERT_EQ(inspector.tracer().gpuScene().lightCount(), 1);
    const auto paths = inspector.record(24, 24, 256, 0);   // the floor in front of the balls
    std::map<std::string, int> seen;
    for (const PathRecord& p : paths) {
        const BounceRecord& b = p.bounces.at(0);
        ASSERT_TRUE(b.hit);
        if (b.lightStatus == LightStatus::None) continue;
        ++seen[b.lightName];
        if (b.lightName == "point light 0" || b.lightName == "spot 1") {
            EXPECT_TRUE(b.lightDelta) << b.lightName;
            EXPECT_GT(b.lightMisPdf, 1e30f) << "FLOAT_MAX times the light's choice";
            if (b.lightStatus == LightStatus::Visible) {
                EXPECT_EQ(b.lightMisWeight, 1.0f) << b.lightName;
            }
            // A shadow ray ends at the light; none is traced where nothing could arrive (f·L = 0:
            // outside the spot's cone), and the distance then reads -1.
            const glm::vec3 at = scene.lights[b.lightName == "spot 1" ? 1 : 0].position;
            if (b.lightStatus == LightStatus::Zero) {
                EXPECT_EQ(b.lightDistance, -1.0f) << b.lightName;
            } else {
                EXPECT_NEAR(b.lightDistance, glm::length(at - b.position), 1e-3f * glm::length(at - b.position));
            }
        } else if (b.lightName == "sun 2" || b.lightName == "sphere light 0") {
            EXPECT_FALSE(b.lightDelta) << b.lightName;
            EXPECT_NEAR(b.lightMisPdf, b.lightPdf, 1e-3f * b.lightPdf) << "a disc's cone: the pdf it was drawn with";
            if (b.lightName == "sun 2") {
                EXPECT_LT(b.lightDistance, 0.0f) << "at infinity: no end point";
            }
        } else {
            ADD_FAILURE() << "unexpected light name '" << b.lightName << "' (index " << b.lightIndex << ")";
        }
    }
    for (const char* name : {"point light 0", "spot 1", "sun 2", "sphere light 0"}) EXPECT_GT(seen[name], 0) << name;

    // The exports: the name, and "delta" where the number would be FLOAT_MAX.
    const nlohmann::json j = pathsToJson(paths);
    const std::vector<PathRecord> back = pathsFromJson(j);
    bool deltaSeen = false;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const BounceRecord& b = paths[i].bounces[0];
        if (b.lightStatus == LightStatus::None) continue;
        const nlohmann::json& l = j[i]["bounces"][0]["light_sample"];
        EXPECT_EQ(l["light_name"], b.lightName);
        EXPECT_EQ(back[i].bounces[0].lightName, b.lightName);
        EXPECT_EQ(back[i].bounces[0].lightDelta, b.lightDelta);
        if (b.lightDelta) {
            EXPECT_EQ(l["mis_pdf"], "delta");
            deltaSeen = true;
        } else {
            EXPECT_EQ(l["mis_pdf"].get<float>(), b.lightMisPdf);
        }
    }
    EXPECT_TRUE(deltaSeen);
    const std::string csv = pathsToCsv(paths);
    EXPECT_NE(csv.find(",light,light_name,"), std::string::npos);
    EXPECT_NE(csv.find(",light_pdf,light_mis_pdf,"), std::string::npos);
    EXPECT_NE(csv.find(",point light 0,"), std::string::npos);
    EXPECT_NE(csv.find(",delta,"), std::string::npos);
}

} // namespace
} // namespace raylab::test
