// The parameter table: complete, consistent with scene.h, and its accessors reach the right fields.
#include "scene/parameters.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

using namespace raylab;

TEST(SceneParameters, TableCoversTheSectionsWithUniqueKeys) {
    std::set<std::string> keys;
    for (const ParamSpec& p : sceneParameters()) {
        EXPECT_TRUE(keys.insert(std::string(p.key)).second) << "duplicate " << p.key;
        const std::string section(p.section());
        EXPECT_TRUE(section == "camera" || section == "render" || section == "sky" || section == "ao") << p.key;
        EXPECT_FALSE(p.help.empty()) << p.key;
        EXPECT_TRUE(p.get && p.set) << p.key;
        EXPECT_EQ(findParameter(p.key), &p);
    }
    const std::set<std::string> expected = {
        "camera.position", "camera.look_at", "camera.up",        "camera.fov",      "camera.aperture",
        "camera.focus_distance", "render.show_mip_level", "render.stage",           "render.width",
        "render.height",   "render.rpp",     "render.spp",       "render.time",     "render.max_bounces",
        "render.rr_depth", "render.seed",    "render.sampler", "render.diffuse_sampling", "render.ggx_sampling", "render.light_selection", "render.light_sampling", "render.accel", "render.nee",       "render.mis",      "render.adaptive",      "render.exposure",  "render.tone_map", "sky.type",
        "sky.color",       "sky.top",        "sky.bottom",       "sky.rotation",    "sky.strength",
        "ao.distance",     "ao.rays"};
    EXPECT_EQ(keys, expected);
    EXPECT_EQ(findParameter("render.sp"), nullptr);
    EXPECT_EQ(findParameter("spp"), nullptr);
}

TEST(SceneParameters, DefaultsComeFromSceneH) {
    const Scene d;
    EXPECT_EQ(std::get<std::int64_t>(findParameter("render.spp")->defaultValue()), d.render.spp);
    EXPECT_EQ(std::get<double>(findParameter("camera.fov")->defaultValue()), double(d.camera.fovY));
    EXPECT_EQ(std::get<glm::vec3>(findParameter("sky.top")->defaultValue()), d.sky.top);
    EXPECT_EQ(std::get<std::int64_t>(findParameter("render.tone_map")->defaultValue()), int(ToneMap::AcesFit));
    // Every default passes its own range check.
    for (const ParamSpec& p : sceneParameters()) EXPECT_FALSE(checkValue(p, p.defaultValue())) << p.key;
    for (const auto& p : materialParameters()) EXPECT_FALSE(checkValue(p, p.defaultValue())) << p.key;
    for (const auto& p : sphereParameters()) EXPECT_FALSE(checkValue(p, p.defaultValue())) << p.key;
}

TEST(SceneParameters, AccessorsReachTheirOwnField) {
    // Set each parameter to a distinct in-range value; it must read back, and the loader reading the
    // key from a file must produce the same field value (so the key really maps to that field).
    for (const ParamSpec& p : sceneParameters()) {
        SCOPED_TRACE(std::string(p.key));
        ParamValue v;
        std::string json;
        switch (p.type) {
        case ParamType::Int:
        case ParamType::UInt:
            v = std::int64_t(p.key == "render.max_bounces" ? 7 : p.key == "render.show_mip_level" ? 1 : 17);
            json = formatValue(p, v);
            break;
        case ParamType::Float:
            v = 12.5;
            json = "12.5";
            break;
        case ParamType::Vec3:
        case ParamType::Rgb:
            v = glm::vec3(0.25f, 0.5f, p.key == "camera.up" ? 0.0f : 0.75f);
            json = formatValue(p, v);
            break;
        case ParamType::Enum:
            // Whichever canonical name is not the default.
            v = std::int64_t(p.enumNames[0].value == std::get<std::int64_t>(p.defaultValue()) ? p.enumNames[1].value
                                                                                           : p.enumNames[0].value);
            json = "\"" + std::string(p.enumName(std::get<std::int64_t>(v))) + "\"";
            break;
        case ParamType::Bool:
            v = std::int64_t(std::get<std::int64_t>(p.defaultValue()) != 0 ? 0 : 1);
            json = formatValue(p, v);
            break;
        }
        ASSERT_FALSE(checkValue(p, v)) << *checkValue(p, v);
        Scene s;
        p.set(s, v);
        EXPECT_EQ(p.get(s), v);
        // No other parameter changed.
        for (const ParamSpec& q : sceneParameters()) {
            if (&q != &p) {
                EXPECT_EQ(q.get(s), q.defaultValue()) << q.key << " changed with " << p.key;
            }
        }
        const Scene loaded = parseScene(R"({ "objects": [ {} ] })", "p.json",
                                        {std::string(p.key) + "=" + json});
        EXPECT_EQ(p.get(loaded), v);
    }
}

TEST(SceneParameters, RangeChecksAndMessages) {
    const ParamSpec& fov = *findParameter("camera.fov");
    EXPECT_EQ(checkScalar(fov, 0.0).value_or(""), "must be in (0, 180), got 0");
    EXPECT_EQ(checkScalar(fov, 180.0).value_or(""), "must be in (0, 180), got 180");
    EXPECT_FALSE(checkScalar(fov, 179.9));
    EXPECT_FALSE(checkScalar(fov, 1e-6));
    const ParamSpec& spp = *findParameter("render.spp");
    EXPECT_EQ(checkScalar(spp, 0.0).value_or(""), "must be >= 1, got 0");
    EXPECT_EQ(checkScalar(spp, 2.5).value_or(""), "must be an integer, got 2.5");
    EXPECT_EQ(checkScalar(spp, 1e10).value_or(""), "must be <= 2147483647, got 10000000000");
    EXPECT_EQ(checkScalar(spp, std::nan("")).value_or(""), "must be finite, got nan");
    EXPECT_EQ(checkScalar(*findParameter("render.exposure"), -std::numeric_limits<double>::infinity()).value_or(""),
              "must be finite, got -inf");
    const ParamSpec& top = *findParameter("sky.top");
    EXPECT_EQ(checkValue(top, glm::vec3(1.0f, -0.5f, 0.0f)).value_or(""), "component 1 must be >= 0, got -0.5");
    EXPECT_EQ(describeRange(fov), "(0, 180)");
    EXPECT_EQ(describeRange(spp), ">= 1");
    EXPECT_EQ(describeRange(*findParameter("render.tone_map")), "clamp (or none), reinhard, aces");
    EXPECT_EQ(describeRange(*findParameter("camera.position")), "any");
}

TEST(SceneParameters, EnumNamesAndTriggers) {
    const ParamSpec& tm = *findParameter("render.tone_map");
    ASSERT_NE(tm.findEnum("none"), nullptr);
    EXPECT_TRUE(tm.findEnum("none")->alias);
    EXPECT_EQ(tm.findEnum("none")->value, int(ToneMap::Clamp));
    EXPECT_EQ(tm.findEnum("aces")->value, int(ToneMap::AcesFit));
    EXPECT_EQ(tm.findEnum("reinhard")->value, int(ToneMap::Reinhard));
    EXPECT_EQ(tm.findEnum("ACES"), nullptr) << "names are case sensitive";
    EXPECT_EQ(tm.enumName(int(ToneMap::Clamp)), "clamp") << "the canonical name, not the alias";
    EXPECT_EQ(findParameter("sky.type")->findEnum("constant")->value, int(Sky::Type::Constant));
    EXPECT_EQ(findParameter("render.width")->trigger, Trigger::ReloadScene);
    EXPECT_EQ(findParameter("camera.fov")->trigger, Trigger::ResetAccumulation);
    EXPECT_EQ(findParameter("render.exposure")->trigger, Trigger::Redisplay);
}

TEST(SceneParameters, EditDistanceAndSuggestions) {
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
    EXPECT_EQ(editDistance("radius", "radius"), 0u);
    EXPECT_EQ(editDistance("radus", "radius"), 1u);
    EXPECT_EQ(editDistance("flaw", "lawn"), 2u);
    const std::vector<std::string_view> keys = {"width", "height", "spp", "rpp", "max_bounces"};
    EXPECT_EQ(closestMatch("widht", keys), "width");
    EXPECT_EQ(closestMatch("maxbounces", keys), "max_bounces");
    EXPECT_EQ(closestMatch("SPP", keys), "spp") << "case-insensitive distance";
    EXPECT_EQ(closestMatch("colour", keys), "") << "nothing plausible";
    EXPECT_EQ(closestMatch("x", keys), "");
}

TEST(SceneParameters, FormatNumbersShortAndExact) {
    EXPECT_EQ(formatNumber(0.8f), "0.8");
    EXPECT_EQ(formatNumber(0.1), "0.1");
    EXPECT_EQ(formatNumber(64.0), "64");
    EXPECT_EQ(formatNumber(4294967295.0), "4294967295");
    EXPECT_EQ(formatNumber(-20.0), "-20");
    EXPECT_EQ(formatNumber(1e300), "1e+300");
    EXPECT_EQ(formatValue(*findParameter("camera.position"), glm::vec3(0.0f, 1.0f, 6.5f)), "[0, 1, 6.5]");
}
