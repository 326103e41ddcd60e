// Saving never loses anything: every shipped scene and every key of the format survive a save to
// another folder and a reload from another working directory, paths are written relative to the
// saved file, and a save replaces the file atomically.
#include "scene/parameters.h"
#include "scene/scene_keys.h"
#include "scene/scene_loader.h"
#include "scene/scene_save.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kScenes = fs::path(RAYLAB_SOURCE_DIR) / "scenes";

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_scene_save_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Runs the enclosing scope from another working directory.
class WorkingDirectory {
public:
    explicit WorkingDirectory(const fs::path& dir) : previous_(fs::current_path()) { fs::current_path(dir); }
    ~WorkingDirectory() { fs::current_path(previous_); }
    WorkingDirectory(const WorkingDirectory&) = delete;
    WorkingDirectory& operator=(const WorkingDirectory&) = delete;

private:
    fs::path previous_;
};

// A path as written in `scene` (relative to its file's directory), as an absolute path.
fs::path resolved(const Scene& scene, const std::string& written) {
    if (written.empty()) return {};
    return fs::absolute(scene.sourcePath.parent_path() / written).lexically_normal();
}

void expectSameTexture(const Texture& a, const Texture& b, const std::string& what) {
    EXPECT_EQ(a.wrapU, b.wrapU) << what;
    EXPECT_EQ(a.wrapV, b.wrapV) << what;
    ASSERT_EQ(a.levels.size(), b.levels.size()) << what;
    ASSERT_FALSE(a.levels.empty()) << what;
    EXPECT_EQ(a.levels[0].width, b.levels[0].width) << what;
    EXPECT_EQ(a.levels[0].height, b.levels[0].height) << what;
    EXPECT_TRUE(a.levels[0].texels == b.levels[0].texels) << what << ": texels differ";
}

template <class Target>
void expectSameFields(const std::vector<FieldSpec<Target>>& table, const Target& a, const Target& b,
                      const std::string& where) {
    for (const FieldSpec<Target>& spec : table)
        EXPECT_TRUE(spec.get(a) == spec.get(b))
            << where << spec.key << ": " << formatValue(spec, spec.get(a)) << " vs " << formatValue(spec, spec.get(b));
}

// A material's name; a glTF material's name starts with its mesh file as written, which is compared
// as the file it resolves to.
std::string materialName(const Scene& s, int index) {
    if (index < 0) return "(none)";
    const Material& m = s.materials.at(std::size_t(index));
    const std::size_t hash = m.name.find('#');
    if (!m.fromGltf || hash == std::string::npos) return m.name;
    return resolved(s, m.name.substr(0, hash)).string() + m.name.substr(hash);
}

// Everything a scene holds except where it came from: every field of every parameter table, the
// files it names (as the files they resolve to), the meshes' data and the decoded textures.
void expectSameScene(const Scene& a, const Scene& b) {
    expectSameFields(sceneParameters(), a, b, "");
    EXPECT_EQ(a.sky.map.empty() ? fs::path() : fs::absolute(a.sky.map).lexically_normal(),
              b.sky.map.empty() ? fs::path() : fs::absolute(b.sky.map).lexically_normal())
        << "sky.map";
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        const Material& ma = a.materials[i];
        const Material& mb = b.materials[i];
        const std::string where = "materials." + ma.name + ".";
        EXPECT_EQ(materialName(a, int(i)), materialName(b, int(i)));
        EXPECT_EQ(ma.fromGltf, mb.fromGltf) << where;
        expectSameFields(materialParameters(), ma, mb, where);
        for (const TextureSlot& slot : textureSlots()) {
            const std::string what = where + std::string(slot.key);
            if (!ma.fromGltf) {
                EXPECT_EQ(resolved(a, ma.*slot.file), resolved(b, mb.*slot.file)) << what;
            }
            ASSERT_EQ(ma.*slot.index < 0, mb.*slot.index < 0) << what;
            if (ma.*slot.index >= 0)
                expectSameTexture(a.textures.at(std::size_t(ma.*slot.index)), b.textures.at(std::size_t(mb.*slot.index)),
                                  what);
        }
    }
    EXPECT_EQ(a.textures.size(), b.textures.size());
    ASSERT_EQ(a.spheres.size(), b.spheres.size());
    for (std::size_t i = 0; i < a.spheres.size(); ++i) {
        const std::string where = "objects." + std::to_string(i) + ".";
        expectSameFields(sphereParameters(), a.spheres[i], b.spheres[i], where);
        expectSameFields(transformParameters(), a.spheres[i].transform, b.spheres[i].transform, where);
        EXPECT_EQ(materialName(a, a.spheres[i].material), materialName(b, b.spheres[i].material)) << where;
    }
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i) {
        const Mesh& ma = a.meshes[i];
        const Mesh& mb = b.meshes[i];
        const std::string where = "objects." + std::to_string(a.spheres.size() + i) + ".";
        EXPECT_EQ(resolved(a, ma.file), resolved(b, mb.file)) << where << "file";
        EXPECT_TRUE(ma.positions == mb.positions) << where << "positions";
        EXPECT_TRUE(ma.normals == mb.normals) << where << "normals";
        EXPECT_TRUE(ma.uvs == mb.uvs) << where << "uvs";
        EXPECT_TRUE(ma.triangles == mb.triangles) << where << "indices";
        EXPECT_EQ(materialName(a, ma.material), materialName(b, mb.material)) << where << "material";
        ASSERT_EQ(ma.triangleMaterials.size(), mb.triangleMaterials.size()) << where;
        for (std::size_t t = 0; t < ma.triangleMaterials.size(); ++t)
            ASSERT_EQ(materialName(a, ma.triangleMaterials[t]), materialName(b, mb.triangleMaterials[t])) << where << t;
        expectSameFields(transformParameters(), ma.transform, mb.transform, where);
    }
    EXPECT_EQ(a.warnings, b.warnings);
}

std::vector<fs::path> shippedScenes() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(kScenes))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// Saves `scene` as `file` and loads it back from the working directory `from`.
Scene saveAndReload(const Scene& scene, const fs::path& file, const fs::path& from) {
    saveSceneFile(scene, file);
    const WorkingDirectory cwd(from);
    return loadScene(file);
}

// Values of `spec` other than `current` that its range allows, the likeliest first.
std::vector<ParamValue> otherValues(const ValueSpec& spec, const ParamValue& current) {
    std::vector<ParamValue> candidates;
    switch (spec.type) {
    case ParamType::Enum:
        for (const EnumName& e : spec.enumNames)
            if (!e.alias) candidates.push_back(std::int64_t(e.value));
        break;
    case ParamType::Bool: candidates.push_back(std::int64_t(1 - std::get<std::int64_t>(current))); break;
    case ParamType::Int:
    case ParamType::UInt:
        for (std::int64_t step : {1, -1}) candidates.push_back(std::get<std::int64_t>(current) + step);
        break;
    case ParamType::Float:
        for (double step : {0.25, -0.25}) candidates.push_back(std::get<double>(current) + step);
        candidates.push_back(std::get<double>(current) * 0.5);
        break;
    case ParamType::Vec3:
    case ParamType::Rgb: {
        const glm::vec3 v = std::get<glm::vec3>(current);
        const glm::vec3 step(0.125f, 0.25f, 0.375f);
        for (const glm::vec3& c : {v + step, v - step, v * 1.5f, v * 0.5f}) candidates.push_back(c);
        break;
    }
    }
    std::vector<ParamValue> out;
    for (const ParamValue& c : candidates)
        if (!(c == current) && !checkValue(spec, c)) out.push_back(c);
    return out;
}

// A scene with one of everything the keys address, beside the shipped scenes so its files resolve.
Scene keyBaseScene() {
    return parseScene(R"({
        "sky": { "map": "sky_procedural.hdr" },
        "materials": { "m": {}, "n": { "albedo": 0.5 } },
        "objects": [
            { "type": "sphere", "material": "m" },
            { "type": "mesh", "material": "m", "positions": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2],
              "uvs": [0, 0, 1, 0, 0, 1], "displacement_texture": "textures/bricks_height.ppm", "displacement_scale": 0.1 }
        ] })",
                      (kScenes / "keys_base.json").string());
}

// A value for a key without a table entry (a file or a material name), other than the current one.
std::string otherText(const std::string& key, const fs::path& otherSky) {
    if (key == "sky.map") return otherSky.string();
    for (const PathKey& p : pathKeys())
        if (p.scope == PathScope::Material && key.ends_with("." + std::string(p.key))) return "textures/bricks.ppm";
    if (key.ends_with(".material")) return "n";
    if (key.ends_with(".displacement_texture")) return "textures/bricks.ppm";
    return "";
}

} // namespace

TEST(SceneSave, EveryShippedSceneReloadsTheSameFromAnotherFolderAndWorkingDirectory) {
    const fs::path dir = scratch("shipped");
    fs::create_directories(dir / "saved" / "deeper");
    fs::create_directories(dir / "elsewhere");
    const std::vector<fs::path> files = shippedScenes();
    ASSERT_GE(files.size(), 14u);
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.filename().string());
        // Opened by a relative path, as the README does.
        const Scene original = loadScene(fs::relative(f));
        Scene again;
        ASSERT_NO_THROW(again = saveAndReload(original, dir / "saved" / "deeper" / f.filename(), dir / "elsewhere"));
        expectSameScene(original, again);
        // A second save from the reloaded scene writes the same text.
        ASSERT_NO_THROW(saveSceneFile(again, dir / "saved" / "again.json"));
        EXPECT_EQ(readText(dir / "saved" / "again.json"),
                  [&] {
                      saveSceneFile(original, dir / "saved" / "first.json");
                      return readText(dir / "saved" / "first.json");
                  }());
    }
}

TEST(SceneSave, PathsAreWrittenRelativeToTheSavedFile) {
    const fs::path dir = scratch("relative");
    const Scene s = loadScene(fs::relative(kScenes / "environment.json"));
    const fs::path sky = fs::absolute(s.sky.map).lexically_normal();
    const nlohmann::json j = sceneToJson(s, dir / "env.json");
    EXPECT_EQ(j["sky"]["map"], sky.lexically_relative(dir).string());
    EXPECT_EQ(sceneToJson(s)["sky"]["map"], "sky_procedural.hdr") << "without a target: relative to the scene's own file";
    const Scene textured = loadScene(fs::relative(kScenes / "textured_bricks.json"));
    fs::create_directories(dir / "sub");
    const nlohmann::json t = sceneToJson(textured, dir / "sub" / "t.json");
    bool sawTexture = false;
    for (const auto& [name, m] : t["materials"].items()) {
        if (!m.contains("albedo_texture")) continue;
        sawTexture = true;
        const fs::path written = m["albedo_texture"].get<std::string>();
        EXPECT_TRUE(written.is_relative()) << written;
        EXPECT_TRUE(fs::exists(dir / "sub" / written)) << written;
    }
    EXPECT_TRUE(sawTexture);
}

TEST(SceneSave, EveryKeyOfTheFormatSurvivesASaveAtANonDefaultValue) {
    const fs::path dir = scratch("keys");
    fs::create_directories(dir / "saved");
    fs::copy_file(kScenes / "sky_procedural.hdr", dir / "other sky.hdr");
    const Scene base = keyBaseScene();
    const std::vector<std::string> keys = sceneKeys(base);
    ASSERT_GT(keys.size(), sceneParameters().size() + materialParameters().size());
    for (const std::string& key : keys) {
        SCOPED_TRACE(key);
        Scene changed = base;
        const SceneParam param = resolveParam(changed, key);
        bool set = false;
        if (param.spec) {
            for (const ParamValue& v : otherValues(*param.spec, param.get(changed))) {
                try {
                    setParam(changed, param, v);
                    set = true;
                    break;
                } catch (const EditError&) {   // a cross-field check refused this one: try the next
                }
            }
        } else {
            const std::string text = otherText(key, dir / "other sky.hdr");
            ASSERT_FALSE(text.empty()) << "no other value known for this key";
            setParam(changed, key, text);
            set = true;
        }
        ASSERT_TRUE(set) << "no other value passes the checks";
        const Scene again = saveAndReload(changed, dir / "saved" / "scene.json", dir);
        expectSameScene(changed, again);
        if (param.spec) {
            EXPECT_FALSE(param.get(again) == param.get(base)) << "the new value was lost";
        }
    }
}

TEST(SceneSave, AdaptiveAtItsDefaultBesideStratifiedOrZsobolIsNotWrittenAsAsked) {
    // render.adaptive true beside stratified or zsobol in a file is refused; at its default it is
    // simply not in effect, and a save must not turn it into a refused file.
    const fs::path dir = scratch("adaptive");
    fs::create_directories(dir);
    for (const std::string sampler : {"stratified", "zsobol"}) {
        SCOPED_TRACE(sampler);
        const Scene s = loadScene(kScenes / "default.json", {"render.sampler=" + sampler});
        EXPECT_FALSE(sceneToJson(s)["render"].contains("adaptive"));
        Scene again;
        ASSERT_NO_THROW(again = saveAndReload(s, dir / "scene.json", dir));
        expectSameScene(s, again);
    }
    const Scene sobol = loadScene(kScenes / "default.json");
    EXPECT_EQ(sceneToJson(sobol)["render"]["adaptive"], true);
    EXPECT_EQ(sceneToJson(loadScene(kScenes / "default.json", {"render.adaptive=false", "render.sampler=zsobol"}))["render"]["adaptive"],
              false);
}

TEST(SceneSave, SavingOverAFileReplacesItWholeAndLeavesNoBackupOrTemporary) {
    const fs::path dir = scratch("atomic");
    const fs::path file = dir / "scene.json";
    std::ofstream(file) << "previous";
    std::ofstream(backupPath(file)) << "a backup left by an interrupted save";
    const Scene s = loadScene(kScenes / "default.json");
    saveSceneFile(s, file);
    EXPECT_NE(readText(file), "previous");
    EXPECT_NO_THROW(loadScene(file));
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"scene.json"}) << "no .bak or temporary file stays";
}

TEST(SceneSave, AFailedSaveLeavesThePreviousFileAsItWas) {
    const fs::path dir = scratch("failed");
    const fs::path file = dir / "scene.json";
    std::ofstream(file) << "previous";
    const Scene good = loadScene(kScenes / "default.json");
    // The temporary file cannot be created: a directory has its name.
    fs::create_directories(dir / ".scene.json.tmp");
    try {
        saveSceneFile(good, file);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": error: cannot write: ", 0), 0u) << e.what();
    }
    EXPECT_EQ(readText(file), "previous");
    EXPECT_FALSE(fs::exists(backupPath(file)));
    fs::remove_all(dir / ".scene.json.tmp");
    // A scene that cannot be written as JSON touches nothing.
    Scene bad = good;
    bad.materials[0].name = "\xff";
    EXPECT_THROW(saveSceneFile(bad, file), SceneError);
    EXPECT_EQ(readText(file), "previous");
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"scene.json"});
}
