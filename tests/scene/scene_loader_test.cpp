// Scene files: shipped scenes load, every kind of bad input gives a located, specific message,
// --set overrides, and sceneToJson round-trips.
#include "scene/scene_loader.h"

#include "support/scene_errors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kScenes = fs::path(RAYLAB_SOURCE_DIR) / "scenes";

// The SceneError message for `text` (with `overrides`), or "<no error>".
std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {},
                    const std::string& file = "test.json") {
    return test::sceneErrorOf(text, overrides, file);
}

// One valid object, for texts that test something else.
constexpr const char* kOneObject = R"("objects": [ { "type": "sphere" } ])";

std::string withObject(const std::string& members) { return "{ " + members + ", " + kOneObject + " }"; }

void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.camera.position, b.camera.position);
    EXPECT_EQ(a.camera.lookAt, b.camera.lookAt);
    EXPECT_EQ(a.camera.up, b.camera.up);
    EXPECT_EQ(a.camera.fovY, b.camera.fovY);
    EXPECT_EQ(a.render.width, b.render.width);
    EXPECT_EQ(a.render.height, b.render.height);
    EXPECT_EQ(a.render.rpp, b.render.rpp);
    EXPECT_EQ(a.render.spp, b.render.spp);
    EXPECT_EQ(a.render.timeBudget, b.render.timeBudget);
    EXPECT_EQ(a.render.maxBounces, b.render.maxBounces);
    EXPECT_EQ(a.render.rrDepth, b.render.rrDepth);
    EXPECT_EQ(a.render.seed, b.render.seed);
    EXPECT_EQ(a.render.exposure, b.render.exposure);
    EXPECT_EQ(a.render.toneMap, b.render.toneMap);
    EXPECT_EQ(a.sky.type, b.sky.type);
    EXPECT_EQ(a.sky.color, b.sky.color);
    EXPECT_EQ(a.sky.top, b.sky.top);
    EXPECT_EQ(a.sky.bottom, b.sky.bottom);
    EXPECT_EQ(a.sky.strength, b.sky.strength);
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_EQ(a.materials[i].name, b.materials[i].name) << i;
        EXPECT_EQ(a.materials[i].albedo, b.materials[i].albedo) << i;
        EXPECT_EQ(a.materials[i].emission, b.materials[i].emission) << i;
        EXPECT_EQ(a.materials[i].emissionStrength, b.materials[i].emissionStrength) << i;
    }
    ASSERT_EQ(a.spheres.size(), b.spheres.size());
    for (size_t i = 0; i < a.spheres.size(); ++i) {
        EXPECT_EQ(a.spheres[i].center, b.spheres[i].center) << i;
        EXPECT_EQ(a.spheres[i].radius, b.spheres[i].radius) << i;
        EXPECT_EQ(a.spheres[i].material, b.spheres[i].material) << i;
    }
}

const Material& materialOf(const Scene& s, size_t sphere) {
    return s.materials.at(static_cast<size_t>(s.spheres.at(sphere).material));
}

} // namespace

// ------------------------------------------------------------------------------------------------
// Valid input

TEST(SceneLoader, EveryShippedSceneLoads) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(kScenes))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 3u) << "expected at least default, furnace and closed_furnace in " << kScenes;
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.string());
        Scene s;
        ASSERT_NO_THROW(s = loadScene(f));
        EXPECT_EQ(s.sourcePath, f);
        EXPECT_FALSE(s.spheres.empty() && s.meshes.empty());
    }
}

TEST(SceneLoader, DefaultSceneIsWhatTheBriefAsksFor) {
    const Scene s = loadScene(kScenes / "default.json");
    EXPECT_EQ(s.render.width, 640);
    EXPECT_EQ(s.render.height, 360);
    EXPECT_EQ(s.render.spp, 64);
    EXPECT_EQ(s.render.rpp, 1);
    EXPECT_EQ(s.render.maxBounces, 8);
    EXPECT_EQ(s.render.rrDepth, 3);
    EXPECT_EQ(s.render.toneMap, ToneMap::AcesFit);
    EXPECT_EQ(s.sky.type, Sky::Type::Gradient);
    int emissive = 0;
    float largest = 0.0f;
    for (size_t i = 0; i < s.spheres.size(); ++i) {
        emissive += materialOf(s, i).emissionStrength > 0.0f ? 1 : 0;
        largest = std::max(largest, s.spheres[i].radius);
    }
    EXPECT_GE(emissive, 1);
    EXPECT_GE(largest, 100.0f) << "no ground sphere";
}

TEST(SceneLoader, FurnaceScenesAreSetUpForTheirAnalyticAnswers) {
    const Scene f = loadScene(kScenes / "furnace.json");
    ASSERT_EQ(f.spheres.size(), 1u);
    EXPECT_EQ(f.sky.type, Sky::Type::Constant);
    EXPECT_EQ(f.sky.color * f.sky.strength, glm::vec3(1.0f));
    EXPECT_EQ(materialOf(f, 0).albedo, glm::vec3(0.5f));
    EXPECT_EQ(materialOf(f, 0).radiance(), glm::vec3(0.0f));
    EXPECT_GE(f.render.rrDepth, f.render.maxBounces) << "roulette must be off in the furnace";
    // The sphere must cover the whole image: its angular radius asin(r/d) exceeds the angle of the
    // image corner from the view axis, atan(tan(fov/2) * hypot(aspect, 1)).
    const float d = glm::length(f.camera.position - f.spheres[0].center);
    const float aspect = float(f.render.width) / float(f.render.height);
    const float corner = std::atan(std::tan(glm::radians(f.camera.fovY) / 2.0f) * std::hypot(aspect, 1.0f));
    EXPECT_GT(std::asin(f.spheres[0].radius / d), corner);

    const Scene c = loadScene(kScenes / "closed_furnace.json");
    ASSERT_EQ(c.spheres.size(), 1u);
    EXPECT_LT(glm::length(c.camera.position - c.spheres[0].center), c.spheres[0].radius);
    const Material& m = materialOf(c, 0);
    EXPECT_EQ(m.albedo, glm::vec3(0.5f));
    EXPECT_EQ(m.radiance(), glm::vec3(0.5f));   // Le / (1 - a) = 1
    EXPECT_EQ(c.sky.color * c.sky.strength, glm::vec3(0.0f));
    EXPECT_EQ(c.render.maxBounces, 64);
    EXPECT_EQ(c.render.rrDepth, 3);
}

TEST(SceneLoader, MissingKeysTakeTheDefaultsOfSceneH) {
    const Scene s = parseScene(R"({ "objects": [ {} ] })", "min.json");
    const Scene d;
    EXPECT_EQ(s.sourcePath, fs::path("min.json"));
    EXPECT_EQ(s.camera.position, d.camera.position);
    EXPECT_EQ(s.camera.fovY, d.camera.fovY);
    EXPECT_EQ(s.render.width, d.render.width);
    EXPECT_EQ(s.render.spp, d.render.spp);
    EXPECT_EQ(s.render.toneMap, d.render.toneMap);
    EXPECT_EQ(s.sky.type, d.sky.type);
    EXPECT_EQ(s.sky.top, d.sky.top);
    // An object without type or material: a unit sphere of the built-in "default" material.
    ASSERT_EQ(s.spheres.size(), 1u);
    EXPECT_EQ(s.spheres[0].radius, 1.0f);
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].name, "default");
    EXPECT_EQ(s.materials[0].albedo, Material{}.albedo);
}

TEST(SceneLoader, ValuesColoursAliasesAndMaterialReferences) {
    const Scene s = parseScene(R"(
        /* block comment */ {
          "render": { "tone_map": "none", "spp": 128.0, "seed": 4294967295, "time": 2.5 },
          "sky": { "type": "constant", "color": 0.25 },           // one number = grey
          "materials": { "zinc": { "albedo": [0.1, 0.2, 0.3] },
                         "default": { "albedo": 0.3 },
                         "amber": { "emission": [1, 0.5, 0], "strength": 2 } },
          "objects": [ { "material": "zinc" }, { "material": "amber", "radius": 0.5 }, {} ]
        })",
                               "x.json");
    EXPECT_EQ(s.render.toneMap, ToneMap::Clamp);
    EXPECT_EQ(s.render.spp, 128);
    EXPECT_EQ(s.render.seed, 4294967295u);
    EXPECT_EQ(s.render.timeBudget, 2.5);
    EXPECT_EQ(s.sky.color, glm::vec3(0.25f));
    // Materials are sorted by name; spheres point at the right ones; a defined "default" is used.
    ASSERT_EQ(s.materials.size(), 3u);
    EXPECT_EQ(s.materials[0].name, "amber");
    EXPECT_EQ(s.materials[1].name, "default");
    EXPECT_EQ(s.materials[2].name, "zinc");
    EXPECT_EQ(materialOf(s, 0).albedo, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(materialOf(s, 1).radiance(), glm::vec3(2.0f, 1.0f, 0.0f));
    EXPECT_EQ(materialOf(s, 2).albedo, glm::vec3(0.3f));
}

// ------------------------------------------------------------------------------------------------
// Bad input: message text, file, line:column and path

TEST(SceneLoader, MalformedJsonGivesLineColumnAndTheParserReason) {
    const std::string text = "{\n"
                             "  \"render\": {\n"
                             "    \"spp\": 64,\n"
                             "  }\n"   // trailing comma: '}' at 4:3 is where a key was expected
                             "}\n";
    EXPECT_EQ(errorOf(text, {}, "scenes/bad.json"),
              "scenes/bad.json:4:3: error: syntax error while parsing object key - unexpected '}'; "
              "expected string literal");

    // Comments and multi-byte characters before the error do not shift the column.
    const std::string text2 = "// é comment { [\n"
                              "{ \"sky\": { \"type\": /* ö */ constant } }";
    EXPECT_EQ(errorOf(text2).substr(0, 29), "test.json:2:28: error: syntax") << errorOf(text2);

    EXPECT_EQ(errorOf(""), "test.json:1:1: error: syntax error while parsing value - unexpected end of input; "
                           "expected '[', '{', or a literal");
    const std::string unterminated = "{ \"objects\": [ {} ]\n";
    EXPECT_NE(errorOf(unterminated).find("test.json:2:1: error: syntax error while parsing object - "
                                         "unexpected end of input"),
              std::string::npos)
        << errorOf(unterminated);
}

TEST(SceneLoader, UnknownKeysNameTheKeyAndSuggestTheClosest) {
    const std::string text = "{\n"
                             "  \"objects\": [\n"
                             "    { \"type\": \"sphere\", \"radus\": 2 }\n"
                             "  ]\n"
                             "}";
    EXPECT_EQ(errorOf(text),
              "test.json:3:25: error: objects[0].radus: unknown key 'radus' in objects[0]; did you mean 'radius'?");

    EXPECT_EQ(errorOf(withObject(R"("render": { "max_bounce": 2 })")),
              "test.json:1:15: error: render.max_bounce: unknown key 'max_bounce' in render; did you mean "
              "'max_bounces'?");
    EXPECT_EQ(errorOf(withObject(R"("camra": {})")),
              "test.json:1:3: error: camra: unknown key 'camra' at the top level; did you mean 'camera'?");
    EXPECT_EQ(errorOf(withObject(R"("materials": { "red": { "albedo": 1, "emision": 1 } })")),
              "test.json:1:40: error: materials.red.emision: unknown key 'emision' in materials.red; did you mean "
              "'emission'?");
    // Nothing close: list what is allowed instead of guessing.
    EXPECT_EQ(errorOf(withObject(R"("sky": { "brightness": 2 })")),
              "test.json:1:12: error: sky.brightness: unknown key 'brightness' in sky (known keys: map, type, "
              "color, top, bottom, rotation, strength)");
}

TEST(SceneLoader, WrongTypes) {
    EXPECT_EQ(errorOf(withObject(R"("camera": { "fov": "wide" })")),
              "test.json:1:22: error: camera.fov: expected a number, got string");
    EXPECT_EQ(errorOf(withObject(R"("render": { "spp": [64] })")),
              "test.json:1:22: error: render.spp: expected an integer, got array");
    EXPECT_EQ(errorOf(withObject(R"("render": { "spp": 64.5 })")),
              "test.json:1:22: error: render.spp: must be an integer, got 64.5");
    EXPECT_EQ(errorOf(withObject(R"("camera": { "position": [0, 1] })")),
              "test.json:1:27: error: camera.position: expected 3 numbers, got 2");
    EXPECT_EQ(errorOf(withObject(R"("camera": { "position": 1 })")),
              "test.json:1:27: error: camera.position: expected [x, y, z], an array of 3 numbers, got number");
    EXPECT_EQ(errorOf(withObject(R"("camera": { "up": [0, true, 0] })")),
              "test.json:1:25: error: camera.up[1]: expected a number, got boolean");
    EXPECT_EQ(errorOf(withObject(R"("sky": { "top": "blue" })")),
              "test.json:1:19: error: sky.top: expected a colour, [r, g, b] or one number for grey, got string");
    EXPECT_EQ(errorOf(withObject(R"("render": { "tone_map": 2 })")),
              "test.json:1:27: error: render.tone_map: expected a string (clamp, reinhard, aces, none), got number");
    EXPECT_EQ(errorOf(withObject(R"("render": { "tone_map": "acse" })")),
              "test.json:1:27: error: render.tone_map: unknown value 'acse'; did you mean 'aces'?");
    EXPECT_EQ(errorOf(withObject(R"("render": [])")),
              "test.json:1:13: error: render: expected an object { ... }, got array");
    EXPECT_EQ(errorOf(R"({ "objects": { "type": "sphere" } })"),
              "test.json:1:14: error: objects: expected an array [ { ... }, ... ], got object");
    EXPECT_EQ(errorOf(R"({ "objects": [ 1 ] })"),
              "test.json:1:16: error: objects[0]: expected an object { \"type\": \"sphere\", ... }, got number");
    EXPECT_EQ(errorOf(R"([ { "objects": [] } ])"),
              "test.json:1:1: error: (top level): a scene file must be a JSON object { ... }, got array");
}

TEST(SceneLoader, OutOfRangeValues) {
    const std::string text = "{\n"
                             "  \"objects\": [\n"
                             "    { \"radius\": 1 },\n"
                             "    { \"radius\": 2 },\n"
                             "    { \"center\": [0, 0, 0],\n"
                             "      \"radius\": -1 }\n"
                             "  ]\n"
                             "}";
    EXPECT_EQ(errorOf(text, {}, "scenes/mine.json"),
              "scenes/mine.json:6:17: error: objects[2].radius: must be > 0, got -1");
    EXPECT_EQ(errorOf(R"({ "objects": [ { "radius": 0 } ] })"),
              "test.json:1:28: error: objects[0].radius: must be > 0, got 0");
    EXPECT_EQ(errorOf(withObject(R"("camera": { "fov": 180 })")),
              "test.json:1:22: error: camera.fov: must be in (0, 180), got 180");
    EXPECT_EQ(errorOf(withObject(R"("render": { "width": 0 })")),
              "test.json:1:24: error: render.width: must be in [1, 16384], got 0");
    EXPECT_EQ(errorOf(withObject(R"("render": { "height": 16385 })")),
              "test.json:1:25: error: render.height: must be in [1, 16384], got 16385");
    EXPECT_EQ(errorOf(withObject(R"("render": { "rpp": 1025 })")),
              "test.json:1:22: error: render.rpp: must be in [1, 1024], got 1025");
    EXPECT_EQ(errorOf(withObject(R"("render": { "spp": 0 })")),
              "test.json:1:22: error: render.spp: must be >= 1, got 0");
    EXPECT_EQ(errorOf(withObject(R"("render": { "spp": 3000000000 })")),
              "test.json:1:22: error: render.spp: must be <= 2147483647, got 3000000000");
    EXPECT_EQ(errorOf(withObject(R"("render": { "time": -1 })")),
              "test.json:1:23: error: render.time: must be >= 0, got -1");
    EXPECT_EQ(errorOf(withObject(R"("render": { "max_bounces": 1025 })")),
              "test.json:1:30: error: render.max_bounces: must be in [0, 1024], got 1025");
    EXPECT_EQ(errorOf(withObject(R"("render": { "rr_depth": -1 })")),
              "test.json:1:27: error: render.rr_depth: must be >= 0, got -1");
    EXPECT_EQ(errorOf(withObject(R"("render": { "seed": -1 })")),
              "test.json:1:23: error: render.seed: must be in [0, 4294967295], got -1");
    EXPECT_EQ(errorOf(withObject(R"("render": { "seed": 4294967296 })")),
              "test.json:1:23: error: render.seed: must be in [0, 4294967295], got 4294967296");
    EXPECT_EQ(errorOf(withObject(R"("render": { "exposure": 20.5 })")),
              "test.json:1:27: error: render.exposure: must be in [-20, 20], got 20.5");
    EXPECT_EQ(errorOf(withObject(R"("sky": { "strength": -0.5 })")),
              "test.json:1:24: error: sky.strength: must be >= 0, got -0.5");
    EXPECT_EQ(errorOf(withObject(R"("materials": { "red": { "albedo": [0.5, 1.5, 0] } })")),
              "test.json:1:43: error: materials.red.albedo[1]: must be in [0, 1], got 1.5");
    EXPECT_EQ(errorOf(withObject(R"("materials": { "red": { "albedo": 2 } })")),
              "test.json:1:37: error: materials.red.albedo: must be in [0, 1], got 2");
    EXPECT_EQ(errorOf(withObject(R"("materials": { "glow": { "emission": [1, -1, 0] } })")),
              "test.json:1:44: error: materials.glow.emission[1]: must be >= 0, got -1");
    EXPECT_EQ(errorOf(withObject(R"("materials": { "glow": { "strength": -2 } })")),
              "test.json:1:40: error: materials.glow.strength: must be >= 0, got -2");
    // Finite as a double but not as a float.
    EXPECT_EQ(errorOf(R"({ "objects": [ { "radius": 1e300 } ] })"),
              "test.json:1:28: error: objects[0].radius: is too large for a 32-bit float (magnitude must be <= "
              "3.4028235e+38), got 1e+300");
}

TEST(SceneLoader, NonFiniteNumbersAreRejectedWhereTheyAre) {
    // JSON has no NaN/Infinity literals; numbers beyond a double's range would overflow to inf.
    const std::string text = "{\n"
                             "  \"objects\": [\n"
                             "    { \"radius\": 1 },\n"
                             "    { \"center\": [0, -1e999, 0] }\n"
                             "  ]\n"
                             "}";
    EXPECT_EQ(errorOf(text), "test.json:4:21: error: objects[1].center[1]: must be finite, got -1e999 "
                             "(too large for a double)");
    EXPECT_EQ(errorOf(withObject(R"("camera": { "fov": 1e400 })")),
              "test.json:1:22: error: camera.fov: must be finite, got 1e400 (too large for a double)");
    // Inside a nested array and as the top-level value.
    EXPECT_EQ(errorOf("[[1], [2, 1E+999]]"), "test.json:1:11: error: [1][1]: must be finite, got 1E+999 (too large "
                                             "for a double)");
}

TEST(SceneLoader, UnknownMaterialsAndObjectTypes) {
    const std::string text = "{\n"
                             "  \"materials\": { \"green\": { \"albedo\": [0.1, 0.8, 0.1] }, \"grey\": {} },\n"
                             "  \"objects\": [ { \"type\": \"sphere\", \"material\": \"gren\" } ]\n"
                             "}";
    EXPECT_EQ(errorOf(text),
              "test.json:3:48: error: objects[0].material: unknown material 'gren'; did you mean 'green'?");
    EXPECT_EQ(errorOf(R"({ "materials": { "a": {}, "b": {} }, "objects": [ { "material": "chrome" } ] })"),
              "test.json:1:65: error: objects[0].material: unknown material 'chrome' (defined materials: a, b)");
    EXPECT_EQ(errorOf(R"({ "objects": [ { "material": "chrome" } ] })"),
              "test.json:1:30: error: objects[0].material: unknown material 'chrome' (there are no defined materials)");
    EXPECT_EQ(errorOf(R"({ "objects": [ { "material": 3 } ] })"),
              "test.json:1:30: error: objects[0].material: expected a material name (a string), got number");
    EXPECT_EQ(errorOf(R"({ "objects": [ {}, { "type": "sphre" } ] })"),
              "test.json:1:30: error: objects[1].type: unknown object type 'sphre'; did you mean 'sphere'?");
    EXPECT_EQ(errorOf(R"({ "objects": [ { "type": "cube" } ] })"),
              "test.json:1:26: error: objects[0].type: unknown object type 'cube' (known types: sphere, mesh)");
    EXPECT_EQ(errorOf(R"({ "materials": { "": {} }, "objects": [ {} ] })"),
              "test.json:1:18: error: materials[\"\"]: a material name must not be empty");
}

TEST(SceneLoader, ZeroObjects) {
    EXPECT_EQ(errorOf("{\n  \"objects\": []\n}"),
              "test.json:2:14: error: objects: a scene needs at least one object, got an empty array");
    // No "objects" key: points at the enclosing (top-level) object.
    EXPECT_EQ(errorOf("\n\n  { \"render\": {} }"),
              "test.json:3:3: error: objects: a scene needs at least one object, and there is no \"objects\" array");
}

TEST(SceneLoader, DegenerateCameras) {
    EXPECT_EQ(errorOf(withObject(R"("camera": { "position": [1, 2, 3], "look_at": [1, 2, 3] })")),
              "test.json:1:49: error: camera.look_at: must differ from camera.position (both are [1, 2, 3])");
    EXPECT_EQ(errorOf(withObject(R"("camera": { "up": [0, 0, 2] })")),
              "test.json:1:21: error: camera.up: is parallel to the view direction look_at - position = [0, 0, -1]; "
              "choose an up direction across the view");
    EXPECT_EQ(errorOf(withObject(R"("camera": { "up": [0, 0, 0] })")),
              "test.json:1:21: error: camera.up: must be a non-zero direction, got [0, 0, 0]");
    // The default up is fine until the view direction turns vertical; then `up` is not in the file
    // and the message points at the camera section.
    EXPECT_EQ(errorOf(withObject(R"("camera": { "position": [0, 5, 0], "look_at": [0, 0, 0] })")),
              "test.json:1:13: error: camera.up: is parallel to the view direction look_at - position = [0, -1, 0]; "
              "choose an up direction across the view");
}

TEST(SceneLoader, DuplicateKeys) {
    const std::string text = "{ \"render\": {\n"
                             "    \"spp\": 16,\n"
                             "    \"spp\": 32 },\n" +
                             std::string(kOneObject) + " }";
    EXPECT_EQ(errorOf(text), "test.json:3:5: error: render.spp: duplicate key 'spp' (first given at line 2, column 5)");
}

TEST(SceneLoader, UnreadableFiles) {
    const fs::path missing = fs::path(::testing::TempDir()) / "raylab_no_such_scene.json";
    fs::remove(missing);
    try {
        loadScene(missing);
        FAIL() << "no error for a missing file";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), missing.string() + ": error: cannot read: No such file or directory");
    }
    const fs::path dir = fs::path(::testing::TempDir());
    try {
        loadScene(dir);
        FAIL() << "no error for a directory";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), dir.string() + ": error: cannot read: Is a directory");
    }
}

TEST(SceneLoader, FileErrorsUseThePathAsGiven) {
    const fs::path file = fs::path(::testing::TempDir()) / "raylab_bad_radius.json";
    {
        std::ofstream out(file);
        out << "{\n\t\"objects\": [ { \"radius\": -3 } ]\n}\n";   // a tab counts as one column
    }
    try {
        loadScene(file);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ":2:27: error: objects[0].radius: must be > 0, got -3");
    }
    fs::remove(file);
}

// ------------------------------------------------------------------------------------------------
// Overrides

TEST(SceneOverrides, SetValuesOfEveryKind) {
    const std::string text = R"({ "materials": { "red": { "albedo": [0.8, 0.1, 0.1] } },
                                   "objects": [ { "material": "red" }, { "radius": 3 } ] })";
    const Scene s = parseScene(text, "o.json",
                               {"render.spp=256", "camera.fov=30", "sky.type=constant", "sky.color=0.5",
                                "render.tone_map=reinhard", "materials.red.albedo=[1,0,0]", "objects.0.radius=2",
                                "camera.position=[0, 2, 9]", "render.time=1.5"});
    EXPECT_EQ(s.render.spp, 256);
    EXPECT_EQ(s.camera.fovY, 30.0f);
    EXPECT_EQ(s.sky.type, Sky::Type::Constant);
    EXPECT_EQ(s.sky.color, glm::vec3(0.5f));
    EXPECT_EQ(s.render.toneMap, ToneMap::Reinhard);
    EXPECT_EQ(materialOf(s, 0).albedo, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(s.spheres[0].radius, 2.0f);
    EXPECT_EQ(s.spheres[1].radius, 3.0f);
    EXPECT_EQ(s.camera.position, glm::vec3(0.0f, 2.0f, 9.0f));
    EXPECT_EQ(s.render.timeBudget, 1.5);
}

TEST(SceneOverrides, CreateMissingSectionsAndMaterialsAndLaterOnesWin) {
    // No "sky", "render" or "materials" in the file.
    const Scene s = parseScene(R"({ "objects": [ {} ] })", "o.json",
                               {"sky.type=constant", "sky.strength=3", "render.spp=8", "render.spp=9",
                                "materials.chalk.albedo=0.9", "objects.0.material=chalk",
                                "materials.lamp={\"emission\": 1, \"strength\": 4}"});
    EXPECT_EQ(s.sky.type, Sky::Type::Constant);
    EXPECT_EQ(s.sky.strength, 3.0f);
    EXPECT_EQ(s.render.spp, 9);
    EXPECT_EQ(materialOf(s, 0).name, "chalk");
    EXPECT_EQ(materialOf(s, 0).albedo, glm::vec3(0.9f));
    ASSERT_EQ(s.materials.size(), 2u);
    EXPECT_EQ(s.materials[1].name, "lamp");
    EXPECT_EQ(s.materials[1].radiance(), glm::vec3(4.0f));
}

TEST(SceneOverrides, BadOverridesSayWhichOverride) {
    const std::string text = R"({ "objects": [ { "radius": 1 } ], "render": { "spp": 4 } })";
    EXPECT_EQ(errorOf(text, {"render.spp"}), "--set render.spp: error: expected KEY=VALUE, e.g. render.spp=256");
    EXPECT_EQ(errorOf(text, {"render.spp=abc"}),
              "--set render.spp=abc: error: render.spp: expected an integer, got string");
    EXPECT_EQ(errorOf(text, {"render.spp=0"}), "--set render.spp=0: error: render.spp: must be >= 1, got 0");
    EXPECT_EQ(errorOf(text, {"render.spq=3"}),
              "--set render.spq=3: error: render.spq: unknown key 'spq' in render; did you mean 'spp'?");
    EXPECT_EQ(errorOf(text, {"sky.type=constnt"}),
              "--set sky.type=constnt: error: sky.type: unknown value 'constnt'; did you mean 'constant'?");
    EXPECT_EQ(errorOf(text, {"objects.1.radius=2"}),
              "--set objects.1.radius=2: error: objects[1]: index 1 is past the end of objects (1 element)");
    EXPECT_EQ(errorOf(text, {"objects.first.radius=2"}),
              "--set objects.first.radius=2: error: objects: is an array; expected an element index, got 'first'");
    EXPECT_EQ(errorOf(text, {"render.spp.max=2"}),
              "--set render.spp.max=2: error: render.spp: is a number, so it cannot contain 'max'");
    EXPECT_EQ(errorOf(text, {"render..spp=2"}),
              "--set render..spp=2: error: the key 'render..spp' has an empty part; write it like render.spp");
    EXPECT_EQ(errorOf(text, {"=2"}), "--set =2: error: the key '' has an empty part; write it like render.spp");
    EXPECT_EQ(errorOf(text, {"camera.up=[0,1"}),
              "--set camera.up=[0,1: error: the value is not valid JSON: syntax error while parsing array - "
              "unexpected end of input; expected ']'");
    EXPECT_EQ(errorOf(text, {"objects.0.radius=-2"}),
              "--set objects.0.radius=-2: error: objects[0].radius: must be > 0, got -2");
    // A whole value replaced by an override: problems inside it are the override's.
    EXPECT_EQ(errorOf(text, {"objects.0={\"radius\": 0}"}),
              "--set objects.0={\"radius\": 0}: error: objects[0].radius: must be > 0, got 0");
    // Objects created by an override where an array was needed.
    EXPECT_EQ(errorOf(R"({ "render": {} })", {"objects.0.radius=2"}),
              "--set objects.0.radius=2: error: objects: expected an array [ { ... }, ... ], got object");
}

TEST(SceneOverrides, CameraChecksBlameTheOverrideThatBrokeThem) {
    // Looking straight down with the default up: the override caused it, though it set another key.
    EXPECT_EQ(errorOf(R"({ "objects": [ {} ] })", {"render.spp=2", "camera.position=[0, 9, 0]"}),
              "--set camera.position=[0, 9, 0]: error: camera.up: is parallel to the view direction look_at - "
              "position = [0, -1, 0]; choose an up direction across the view");
    EXPECT_EQ(errorOf(R"({ "objects": [ {} ] })", {"camera.look_at=[0,1,6]"}),
              "--set camera.look_at=[0,1,6]: error: camera.look_at: must differ from camera.position (both are "
              "[0, 1, 6])");
}

TEST(SceneOverrides, FileErrorsStayFileErrors) {
    // The override is fine; the error is in the file and is reported there.
    const std::string text = "{ \"camera\": { \"fov\": 0 },\n  \"objects\": [ {} ] }";
    EXPECT_EQ(errorOf(text, {"render.spp=2"}), "test.json:1:22: error: camera.fov: must be in (0, 180), got 0");
    // ...and an override can fix it.
    EXPECT_EQ(errorOf(text, {"camera.fov=45"}), "<no error>");
}

// ------------------------------------------------------------------------------------------------
// Writing scenes back

TEST(SceneRoundTrip, DefaultSceneSurvivesSceneToJsonAndParse) {
    const Scene original = loadScene(kScenes / "default.json");
    const nlohmann::json j = sceneToJson(original);
    const Scene again = parseScene(j.dump(2), "roundtrip.json");
    expectSameScene(original, again);
    // Float fields are written in their short form.
    EXPECT_EQ(j["materials"]["red"]["albedo"][0].dump(), "0.8");
    EXPECT_EQ(j["render"]["tone_map"], "aces");
    EXPECT_EQ(j["objects"][0]["type"], "sphere");
}

TEST(SceneRoundTrip, EveryShippedSceneAndAwkwardValuesRoundTrip) {
    for (const char* name : {"furnace.json", "closed_furnace.json"}) {
        const Scene s = loadScene(kScenes / name);
        expectSameScene(s, parseScene(sceneToJson(s).dump(), name));
    }
    Scene s = parseScene(R"({ "objects": [ {} ] })", "x.json");  // built-in default material
    s.render.timeBudget = 0.1f;        // a double that is not the double nearest to 0.1
    s.render.seed = 4294967295u;
    s.render.toneMap = ToneMap::Clamp;
    s.camera.fovY = 33.333333f;
    s.sky.top = glm::vec3(1e-7f, 3.4e38f, 0.1f);
    s.spheres[0].center = glm::vec3(-0.0f, 1e30f, 123456.789f);
    expectSameScene(s, parseScene(sceneToJson(s).dump(), "x.json"));
    EXPECT_EQ(sceneToJson(s)["render"]["tone_map"], "clamp") << "aliases are never written";
}

TEST(SceneRoundTrip, BadMaterialIndexIsReported) {
    Scene s = parseScene(R"({ "objects": [ {} ] })", "x.json");
    s.spheres[0].material = 5;
    try {
        sceneToJson(s);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "sceneToJson: error: objects[0].material: index 5 is out of range (1 materials)");
    }
}
