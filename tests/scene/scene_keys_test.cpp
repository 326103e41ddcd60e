#include "scene/scene_keys.h"

#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>

namespace raylab {
namespace {

Scene twoSpheres() {
    return parseScene(R"({"materials": {"red": {"albedo": [0.8, 0.1, 0.1]}, "lamp": {"emission": 1, "strength": 4}},
                          "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"},
                                      {"type": "sphere", "center": [3, 0, 0], "radius": 0.5, "material": "lamp"}]})",
                      "two.json");
}

// The EditError a live edit gives, or "no error".
std::string errorOf(Scene& s, const std::string& key, const std::string& value) {
    try {
        setParam(s, key, value);
    } catch (const EditError& e) {
        return std::string(e.what());
    }
    return std::string("no error");
}

TEST(SceneKeys, SetsSceneKeysAndReportsTheirTrigger) {
    Scene s = twoSpheres();
    EXPECT_EQ(setParam(s, "camera.fov", "55"), Trigger::ResetAccumulation);
    EXPECT_FLOAT_EQ(s.camera.fovY, 55.0f);
    EXPECT_EQ(setParam(s, "render.exposure", "1.5"), Trigger::Redisplay);
    EXPECT_FLOAT_EQ(s.render.exposure, 1.5f);
    EXPECT_EQ(setParam(s, "render.tone_map", "reinhard"), Trigger::Redisplay);
    EXPECT_EQ(s.render.toneMap, ToneMap::Reinhard);
    EXPECT_EQ(setParam(s, "render.tone_map", "\"clamp\""), Trigger::Redisplay);
    EXPECT_EQ(s.render.toneMap, ToneMap::Clamp);
    EXPECT_EQ(setParam(s, "render.width", "320"), Trigger::ReloadScene);
    EXPECT_EQ(s.render.width, 320);
}

TEST(SceneKeys, SetsMaterialsByNameOrIndexAndObjectsByIndex) {
    Scene s = twoSpheres();
    const std::size_t red = s.materials[0].name == "red" ? 0 : 1, lamp = 1 - red;
    setParam(s, "materials.red.albedo", "[0.2, 0.3, 0.4]");
    EXPECT_EQ(s.materials[red].albedo, glm::vec3(0.2f, 0.3f, 0.4f));
    setParam(s, "materials." + std::to_string(lamp) + ".strength", "9");
    EXPECT_FLOAT_EQ(s.materials[lamp].emissionStrength, 9.0f);
    setParam(s, "materials.red.albedo", "0.5");   // one number = grey
    EXPECT_EQ(s.materials[red].albedo, glm::vec3(0.5f));
    EXPECT_EQ(setParam(s, "objects.1.radius", "2"), Trigger::MoveObjects);
    EXPECT_FLOAT_EQ(s.spheres[1].radius, 2.0f);
}

TEST(SceneKeys, LightsTakeTheKeysOfTheirTypeWithTheLoadersChecks) {
    Scene s = parseScene(R"({"objects": [{"type": "sphere"}],
                             "lights": [{"type": "spot", "power": 10}, {"type": "distant"}]})", "lights.json");
    EXPECT_EQ(setParam(s, "lights.0.intensity", "[1, 2, 3]"), Trigger::UpdateMaterials);
    EXPECT_EQ(s.lights[0].intensity, glm::vec3(1, 2, 3));
    EXPECT_EQ(s.lights[0].power, 0.0f) << "the intensity given replaces the power";
    setParam(s, "lights.1.angular_radius", "0.27");
    EXPECT_FLOAT_EQ(s.lights[1].angularRadius, 0.27f);
    EXPECT_NE(errorOf(s, "lights.1.position", "[0, 1, 0]").find("this light has no key 'position'"), std::string::npos);
    EXPECT_NE(errorOf(s, "lights.0.inner_angle", "40").find("must not exceed outer_angle"), std::string::npos);
    EXPECT_NE(errorOf(s, "lights.1.direction", "[0, 0, 0]").find("non-zero direction"), std::string::npos);
    EXPECT_NE(errorOf(s, "lights.1.angular_radius", "90").find("must be in [0, 90)"), std::string::npos);
    EXPECT_NE(errorOf(s, "lights.2.irradiance", "1").find("no light 2"), std::string::npos);
    EXPECT_EQ(s.lights[0].innerAngle, 25.0f);
    const std::vector<std::string> keys = sceneKeys(s);
    EXPECT_NE(std::find(keys.begin(), keys.end(), "lights.1.irradiance"), keys.end());
    EXPECT_EQ(std::find(keys.begin(), keys.end(), "lights.1.position"), keys.end());
}

TEST(SceneKeys, RejectsBadKeysAndValuesWithoutChangingTheScene) {
    Scene s = twoSpheres();
    const Scene before = s;
    auto message = [&](const char* key, const char* value) { return errorOf(s, key, value); };
    EXPECT_NE(message("camera.fvo", "40").find("did you mean 'camera.fov'"), std::string::npos);
    EXPECT_NE(message("camera.fov", "180").find("camera.fov: must be in (0, 180), got 180"), std::string::npos);
    EXPECT_NE(message("render.spp", "1.5").find("render.spp"), std::string::npos);
    EXPECT_NE(message("materials.blue.albedo", "1").find("no material 'blue'"), std::string::npos);
    EXPECT_NE(message("materials.red.albedo", "[2, 0, 0]").find("albedo"), std::string::npos);
    EXPECT_NE(message("materials.red.shininess", "1").find("materials have no key 'shininess'"), std::string::npos);
    EXPECT_NE(message("objects.7.radius", "1").find("no object 7"), std::string::npos);
    EXPECT_NE(message("render.tone_map", "filmic").find("unknown value 'filmic'"), std::string::npos);
    EXPECT_NE(message("camera.position", "[1, 2]").find("expected [x, y, z]"), std::string::npos);
    EXPECT_EQ(sceneToJson(s), sceneToJson(before));
}

// Live values go through the scene file's parser: its depth limit holds, and a value nested past it
// is an error naming the key and the character, for table keys and text keys alike.
TEST(SceneKeys, DeeplyNestedValuesAreLocatedErrorsNotCrashes) {
    Scene s = twoSpheres();
    const Scene before = s;
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    for (const char* key : {"camera.fov", "materials.red.albedo", "render.tone_map", "objects.0.material",
                            "materials.red.albedo_texture", "sky.map"}) {
        const std::string e = errorOf(s, key, deep);
        EXPECT_NE(e.find("nested too deeply"), std::string::npos) << key << ": " << e.substr(0, 200);
        EXPECT_NE(e.find("character 65"), std::string::npos) << key << ": " << e.substr(0, 200);
        EXPECT_LT(e.size(), 300u) << key;
    }
    EXPECT_EQ(s.camera.fovY, before.camera.fovY);
    EXPECT_EQ(s.materials[0].albedo, before.materials[0].albedo);
    EXPECT_EQ(errorOf(s, "camera.fov", "[[[1]]]").find("nested"), std::string::npos) << "shallow values are plain type errors";
}

TEST(SceneKeys, BooleanKeysTakeTrueAndFalse) {
    Scene s = twoSpheres();
    for (const ParamSpec& p : sceneParameters()) {
        if (p.type != ParamType::Bool) continue;
        setParam(s, p.key, "false");
        EXPECT_EQ(std::get<std::int64_t>(p.get(s)), 0) << p.key;
        setParam(s, p.key, "true");
        EXPECT_EQ(std::get<std::int64_t>(p.get(s)), 1) << p.key;
        EXPECT_THROW(setParam(s, p.key, "2"), EditError) << p.key;
    }
}

TEST(SceneKeys, EveryTableKeyResolves) {
    const Scene s = twoSpheres();
    for (const ParamSpec& p : sceneParameters()) EXPECT_EQ(resolveParam(s, p.key).spec, &p) << p.key;
    for (const MaterialParamSpec& p : materialParameters())
        EXPECT_EQ(resolveParam(s, "materials.lamp." + std::string(p.key)).spec, &p);
    for (const SphereParamSpec& p : sphereParameters())
        EXPECT_EQ(resolveParam(s, "objects.0." + std::string(p.key)).spec, &p);
    for (const TransformParamSpec& p : transformParameters())
        EXPECT_EQ(resolveParam(s, "objects.1." + std::string(p.key)).spec, &p);
}

// A scene in scenes/, so that relative texture and sky files resolve: two spheres and an inline
// mesh, displaced so that its displacement keys are written.
const std::string kSceneFile = (std::filesystem::path(RAYLAB_SOURCE_DIR) / "scenes" / "keys_test.json").string();
const char* kSceneText = R"({"materials": {"red": {"albedo": [0.8, 0.1, 0.1]}, "lamp": {"emission": 1, "strength": 4}},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"},
                {"type": "sphere", "center": [3, 0, 0], "radius": 0.5, "material": "lamp"},
                {"type": "mesh", "positions": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2], "material": "red",
                 "uvs": [0, 0, 1, 0, 0, 1], "displacement_texture": "textures/glow.png", "displacement_scale": 0.1}]})";

// A valid value for `key` that differs from the one `scene` holds, as --set and the script write it.
std::string otherValue(const Scene& scene, const std::string& key) {
    const SceneParam param = resolveParam(scene, key);
    if (!param.spec) {
        if (key == "sky.map") return "sky_procedural.hdr";
        if (key.ends_with(".material")) return key == "objects.1.material" ? "red" : "lamp";
        return key.ends_with("albedo_texture") || key.ends_with("emission_texture") ? "textures/glow.png"
                                                                                 : "textures/tiles_mr.png";
    }
    const ValueSpec& spec = *param.spec;
    const ParamValue now = param.get(scene);
    std::optional<ParamValue> next;
    switch (spec.type) {
    case ParamType::Bool: next = std::int64_t(1 - std::get<std::int64_t>(now)); break;
    case ParamType::Enum:
        for (const EnumName& e : spec.enumNames)
            if (!next && !e.alias && e.value != std::get<std::int64_t>(now) && e.name != "map") next = std::int64_t(e.value);
        break;
    case ParamType::Int:
    case ParamType::UInt: {
        const std::int64_t v = std::get<std::int64_t>(now);
        next = checkValue(spec, ParamValue(v + 1)) ? ParamValue(v - 1) : ParamValue(v + 1);
        break;
    }
    case ParamType::Float: next = std::get<double>(now) * 0.5 + 0.3; break;
    case ParamType::Vec3:
    case ParamType::Rgb: next = std::get<glm::vec3>(now) * 0.5f + 0.3f; break;
    }
    EXPECT_FALSE(checkValue(spec, *next)) << key;
    return formatValue(spec, *next);
}

TEST(SceneKeys, EveryKeyTheFileHasIsSetLiveAsSetSetsIt) {
    const Scene scene = parseScene(kSceneText, kSceneFile);
    const std::vector<std::string> keys = sceneKeys(scene);
    // The whole parameter table, every material and texture key, every object key (a mesh's displacement too).
    EXPECT_EQ(keys.size(), sceneParameters().size() + 1 + 2 * (materialParameters().size() + materialFileKeys().size()) +
                               2 * sphereParameters().size() + 3 * (transformParameters().size() + 1) +
                               displacementParameters().size() + 1);
    for (const std::string& key : keys) {
        const std::string value = otherValue(scene, key);
        SCOPED_TRACE(key + "=" + value);
        const Scene viaSet = parseScene(kSceneText, kSceneFile, {key + "=" + value});
        Scene live = scene;
        setParam(live, key, value);
        EXPECT_EQ(sceneToJson(live), sceneToJson(viaSet));
        EXPECT_NE(sceneToJson(live), sceneToJson(scene));
    }
}

TEST(SceneKeys, LiveEditsAndSetShareTheKeyGrammar) {
    Scene s = twoSpheres();
    EXPECT_THROW(setParam(s, "camera..fov", "40"), EditError);
    try {
        setParam(s, "camera..fov", "40");
    } catch (const EditError& e) {
        EXPECT_STREQ(e.what(), "the key 'camera..fov' has an empty part; write it like render.spp");
    }
    try {
        parseScene(kSceneText, kSceneFile, {"camera..fov=40"});
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "--set camera..fov=40: error: the key 'camera..fov' has an empty part; write it like render.spp");
    }
}

TEST(SceneKeys, LiveEditsMeetTheLoadersChecksAndLeaveTheSceneAsItWas) {
    Scene s = parseScene(kSceneText, kSceneFile);
    const nlohmann::json before = sceneToJson(s);
    auto message = [&](const char* key, const char* value) { return errorOf(s, key, value); };
    const std::string position = formatValue(*findParameter("camera.position"), s.camera.position);
    EXPECT_EQ(message("camera.look_at", position.c_str()),
              "camera.look_at: must differ from camera.position (both are " + position + ")");
    EXPECT_EQ(message("sky.type", "map"), "sky.type: 'map' needs sky.map, an equirectangular .hdr or .exr image");
    EXPECT_NE(message("materials.red.albedo_texture", "textures/missing.png").find("cannot read: no such file"),
              std::string::npos);
    EXPECT_EQ(message("materials.red.albedo_texture", "3"),
              "materials.red.albedo_texture: expected the path of an image file (a string), got number");
    EXPECT_EQ(message("sky.map", "missing.hdr"),
              "sky.map: cannot read '" + (std::filesystem::path(kSceneFile).parent_path() / "missing.hdr").string() +
                  "': no such file");
    EXPECT_EQ(message("objects.0.material", "rde"), "objects[0].material: unknown material 'rde'; did you mean 'red'?");
    EXPECT_EQ(sceneToJson(s), before);
}

TEST(SceneKeys, AnObjectMayTakeTheBuiltInDefaultMaterial) {
    Scene s = parseScene(kSceneText, kSceneFile);
    EXPECT_EQ(setParam(s, "objects.2.material", "default"), Trigger::ReloadScene);
    const Material& m = s.materials.at(std::size_t(s.meshes[0].material));
    EXPECT_EQ(m.name, "default");
    EXPECT_EQ(sceneToJson(s), sceneToJson(parseScene(kSceneText, kSceneFile, {"objects.2.material=default"})));
}

} // namespace
} // namespace raylab
