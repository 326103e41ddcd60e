// glTF materials mapped onto raylab's (the table in scenes/FORMAT.md), on the loaded Scene: factors,
// textures from files, data URIs and GLB buffer views, sRGB against linear decoding, wrap modes,
// per-primitive materials, warnings, and located errors. The assets are generated here.
#include "scene/gltf_loader.h"
#include "scene/scene_loader.h"
#include "support/gltf_writer.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_gltf_mat_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "models");
    return dir;
}

float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

// 2×2 grey-ish images with one distinctive texel value each (top-left texel = v, others 255).
std::vector<unsigned char> pixels(int channels, unsigned char v) {
    std::vector<unsigned char> px(std::size_t(4 * channels), 255);
    for (int c = 0; c < channels; ++c) px[std::size_t(c)] = v;
    return px;
}

// Material 0 uses every texture kind: base colour from an external PNG, metallic-roughness from a
// data URI, normal map with a scale, emission with KHR_materials_emissive_strength, clamp/mirror
// sampler, alpha blending (a warning). Material 1 has factors only. The third quad has none.
test::GltfSpec fullSpec(const fs::path& models) {
    test::writePng(models / "base.png", 2, 2, 3, pixels(3, 128));
    test::writePng(models / "normal.png", 2, 2, 3, pixels(3, 128));
    test::writePng(models / "emit.png", 2, 2, 3, pixels(3, 64));
    test::GltfSpec s;
    s.primitiveMaterials = {0, 1, -1};
    const std::string mr = "data:image/png;base64," + test::base64(test::pngBytes(2, 2, 3, pixels(3, 128)));
    s.images = R"([ { "uri": "base.png" }, { "uri": ")" + mr + R"(" }, { "uri": "normal.png" }, { "uri": "emit.png" } ])";
    s.samplers = R"([ { "wrapS": 33071, "wrapT": 33648 } ])";
    s.textures = R"([ { "source": 0, "sampler": 0 }, { "source": 1 }, { "source": 2 }, { "source": 3 } ])";
    s.extensionsUsed = R"(["KHR_materials_emissive_strength"])";
    s.materials = R"([
      { "name": "Everything", "alphaMode": "BLEND",
        "pbrMetallicRoughness": { "baseColorFactor": [0.5, 0.25, 1.0, 0.5], "baseColorTexture": { "index": 0 },
                                  "metallicFactor": 0.75, "roughnessFactor": 0.5,
                                  "metallicRoughnessTexture": { "index": 1 } },
        "normalTexture": { "index": 2, "scale": 0.5 },
        "emissiveFactor": [1, 0.5, 0.25], "emissiveTexture": { "index": 3 },
        "extensions": { "KHR_materials_emissive_strength": { "emissiveStrength": 4 } } },
      { "pbrMetallicRoughness": { "metallicFactor": 0.25, "roughnessFactor": 0.75, "baseColorFactor": [0.2, 0.4, 0.6, 1] } } ])";
    return s;
}

} // namespace

TEST(GltfMaterials, FactorsAndTexturesMapOntoRaylabMaterials) {
    const fs::path dir = scratch("full");
    test::writeGltf(dir / "models" / "quads.gltf", fullSpec(dir / "models"));
    std::ofstream(dir / "scene.json") << R"({ "materials": { "red": { "albedo": [1, 0, 0] } },
      "objects": [ { "type": "mesh", "file": "models/quads.gltf", "transform": { "translation": [0, 0, -3] } } ] })";
    const Scene scene = loadScene(dir / "scene.json");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    ASSERT_EQ(mesh.triangles.size(), 6u);
    // The file's own materials keep their sorted places; glTF ones follow; "default" for the third quad.
    ASSERT_EQ(scene.materials.size(), 4u);
    EXPECT_EQ(scene.materials[0].name, "default");
    EXPECT_EQ(scene.materials[1].name, "red");
    EXPECT_EQ(scene.materials[2].name, "models/quads.gltf#materials[0] Everything");
    EXPECT_EQ(scene.materials[3].name, "models/quads.gltf#materials[1]");
    EXPECT_EQ(scene.materials[mesh.material].name, "default");
    ASSERT_EQ(mesh.triangleMaterials.size(), 6u);
    EXPECT_EQ(mesh.triangleMaterials, (std::vector<int>{2, 2, 3, 3, -1, -1}));

    const Material& a = scene.materials[2];
    EXPECT_TRUE(a.fromGltf);
    EXPECT_EQ(a.albedo, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(a.f0, glm::vec3(0.04f));
    EXPECT_FLOAT_EQ(a.metallic, 0.75f);
    EXPECT_FLOAT_EQ(a.roughness, 0.5f);
    EXPECT_FLOAT_EQ(a.normalScale, 0.5f);
    EXPECT_EQ(a.emission, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_FLOAT_EQ(a.emissionStrength, 4.0f);
    EXPECT_EQ(a.roughnessTextureIndex, a.metallicTextureIndex) << "one image, green and blue channels";
    for (int t : {a.albedoTextureIndex, a.roughnessTextureIndex, a.normalTextureIndex, a.emissionTextureIndex})
        ASSERT_GE(t, 0);
    ASSERT_EQ(scene.textures.size(), 4u);
    // Texel values: the image's top-left texel is row height-1 (v = 0 is the bottom row).
    auto topLeft = [&](int t) { return scene.textures[std::size_t(t)].levels[0].texels[2]; };
    EXPECT_NEAR(topLeft(a.albedoTextureIndex).r, srgbToLinear(128.0f / 255.0f), 1e-6f) << "base colour: sRGB";
    EXPECT_NEAR(topLeft(a.roughnessTextureIndex).g, 128.0f / 255.0f, 1e-6f) << "metallic-roughness: linear";
    EXPECT_NEAR(topLeft(a.normalTextureIndex).b, 128.0f / 255.0f, 1e-6f) << "normal map: linear";
    EXPECT_NEAR(topLeft(a.emissionTextureIndex).r, srgbToLinear(64.0f / 255.0f), 1e-6f) << "emission: sRGB";
    const Texture& base = scene.textures[std::size_t(a.albedoTextureIndex)];
    EXPECT_EQ(base.wrapU, TextureWrap::ClampToEdge);
    EXPECT_EQ(base.wrapV, TextureWrap::MirroredRepeat);
    EXPECT_EQ(scene.textures[std::size_t(a.normalTextureIndex)].wrapU, TextureWrap::Repeat);

    const Material& b = scene.materials[3];
    EXPECT_EQ(b.albedo, glm::vec3(0.2f, 0.4f, 0.6f));
    EXPECT_FLOAT_EQ(b.metallic, 0.25f);
    EXPECT_FLOAT_EQ(b.roughness, 0.75f);
    EXPECT_EQ(b.albedoTextureIndex, -1);
    EXPECT_FLOAT_EQ(b.emissionStrength, 0.0f);

    // alphaMode BLEND is a warning naming the file and the place.
    bool warned = false;
    for (const std::string& w : scene.warnings)
        warned |= w.find("quads.gltf: materials[0].alphaMode: BLEND is ignored") != std::string::npos;
    EXPECT_TRUE(warned);
    // Node transforms still apply (and the object's transform stays separate).
    EXPECT_NEAR(mesh.positions[0].x, -1.0f, 1e-6f);
    EXPECT_NEAR(mesh.positions[0].y, -0.5f, 1e-6f);
    EXPECT_EQ(mesh.transform.translation, glm::vec3(0, 0, -3));
    fs::remove_all(dir);
}

TEST(GltfMaterials, NodeTranslationAndUvFlipWithMaterials) {
    const fs::path dir = scratch("node");
    test::GltfSpec s;
    s.translateX = 5.0f;
    s.materials = R"([ { "pbrMetallicRoughness": { "baseColorFactor": [0.1, 0.2, 0.3, 1] } } ])";
    test::writeGltf(dir / "models" / "q.gltf", s);
    const GltfAsset asset = loadGltfAsset(dir / "models" / "q.gltf");
    ASSERT_EQ(asset.mesh.positions.size(), 4u);
    EXPECT_EQ(asset.mesh.positions[0], glm::vec3(4.0f, -0.5f, 0.0f));
    EXPECT_EQ(asset.mesh.positions[2], glm::vec3(5.0f, 0.5f, 0.0f));
    EXPECT_EQ(asset.mesh.uvs[0], glm::vec2(0.0f, 0.0f)) << "glTF (0, 1) is raylab's (0, 0)";
    EXPECT_EQ(asset.mesh.uvs[2], glm::vec2(1.0f, 1.0f));
    ASSERT_EQ(asset.materials.size(), 1u);
    EXPECT_EQ(asset.materials[0].albedo, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_FLOAT_EQ(asset.materials[0].metallic, 1.0f) << "glTF's default metallicFactor";
    EXPECT_EQ(asset.mesh.triangleMaterials, (std::vector<int>{0, 0}));
    EXPECT_TRUE(loadGltf(dir / "models" / "q.gltf").triangleMaterials.empty()) << "geometry only";
    EXPECT_TRUE(asset.warnings.empty());
    s.extensionsUsed = R"(["KHR_texture_transform"], "extensionsRequired": ["KHR_texture_transform"])";
    test::writeGltf(dir / "models" / "q.gltf", s);
    const GltfAsset required = loadGltfAsset(dir / "models" / "q.gltf");
    ASSERT_EQ(required.warnings.size(), 1u);
    EXPECT_NE(required.warnings[0].find("extensionsRequired: KHR_texture_transform is not supported"), std::string::npos);
    fs::remove_all(dir);
}

TEST(GltfMaterials, AnObjectMaterialOverridesTheFilesAndSavingKeepsThem) {
    const fs::path dir = scratch("override");
    test::writeGltf(dir / "models" / "quads.gltf", fullSpec(dir / "models"));
    std::ofstream(dir / "scene.json") << R"({ "materials": { "red": { "albedo": [1, 0, 0] } },
      "objects": [ { "type": "mesh", "file": "models/quads.gltf", "material": "red" },
                   { "type": "mesh", "file": "models/quads.gltf" },
                   { "type": "mesh", "file": "models/quads.gltf" } ] })";
    const Scene scene = loadScene(dir / "scene.json");
    ASSERT_EQ(scene.meshes.size(), 3u);
    EXPECT_TRUE(scene.meshes[0].triangleMaterials.empty());
    EXPECT_EQ(scene.materials[std::size_t(scene.meshes[0].material)].name, "red");
    EXPECT_EQ(scene.meshes[1].triangleMaterials, scene.meshes[2].triangleMaterials) << "one copy per file";
    EXPECT_EQ(scene.materials.size(), 4u);
    EXPECT_EQ(scene.textures.size(), 4u);
    // Written back, the glTF materials are not in "materials" and the meshes name none.
    const nlohmann::json j = sceneToJson(scene);
    EXPECT_EQ(j["materials"].size(), 2u);
    EXPECT_FALSE(j["objects"][1].contains("material"));
    const fs::path again = dir / "again.json";
    std::ofstream(again) << j.dump();
    const Scene back = loadScene(again);
    EXPECT_EQ(back.materials.size(), 4u);
    EXPECT_EQ(back.meshes[1].triangleMaterials, scene.meshes[1].triangleMaterials);
    fs::remove_all(dir);
}

TEST(GltfMaterials, GlbWithTheImageInABufferView) {
    const fs::path dir = scratch("glb");
    test::GltfSpec s;
    s.glbImage = test::pngBytes(2, 2, 4, pixels(4, 200));
    s.images = R"([ { "bufferView": 3, "mimeType": "image/png" } ])";
    s.textures = R"([ { "source": 0 } ])";
    s.materials = R"([ { "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 }, "metallicFactor": 0 },
                         "emissiveFactor": [0, 0, 0], "emissiveTexture": { "index": 0 } } ])";
    test::writeGlb(dir / "models" / "q.glb", s);
    const GltfAsset asset = loadGltfAsset(dir / "models" / "q.glb");
    ASSERT_EQ(asset.materials.size(), 1u);
    const Material& m = asset.materials[0];
    ASSERT_EQ(m.albedoTextureIndex, 0);
    EXPECT_EQ(m.emissionTextureIndex, -1) << "emissiveFactor 0: the emissive texture has nothing to scale";
    EXPECT_NEAR(asset.textures[0].levels[0].texels[2].r, srgbToLinear(200.0f / 255.0f), 1e-6f);
    EXPECT_NEAR(asset.textures[0].levels[0].texels[2].a, 200.0f / 255.0f, 1e-6f) << "alpha is not decoded";
    fs::remove_all(dir);
}

TEST(GltfMaterials, MissingAndBrokenImagesNameTheFileAndThePlace) {
    const fs::path dir = scratch("errors");
    test::GltfSpec s = fullSpec(dir / "models");
    test::writeGltf(dir / "models" / "quads.gltf", s);
    fs::remove(dir / "models" / "base.png");
    std::ofstream(dir / "scene.json") << R"({
  "objects": [ { "type": "mesh", "file": "models/quads.gltf" } ] })";
    try {
        loadScene(dir / "scene.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir / "scene.json").string() + ":2:42: error: objects[0].file: " +
                      (dir / "models" / "quads.gltf").string() +
                      ": materials[0].pbrMetallicRoughness.baseColorTexture: images[0] 'base.png': cannot read: no such file");
    }
    // An image that is not one: tinygltf's decoder names the image.
    std::ofstream(dir / "models" / "base.png") << "not a png";
    try {
        loadScene(dir / "scene.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("objects[0].file: " + (dir / "models" / "quads.gltf").string() + ": "), std::string::npos) << what;
        EXPECT_NE(what.find("image[0]"), std::string::npos) << what;
    }
    // A texture index that does not exist.
    test::writePng(dir / "models" / "base.png", 2, 2, 3, pixels(3, 128));
    s.materials = R"([ { "normalTexture": { "index": 9 } } ])";
    s.primitiveMaterials = {0};
    test::writeGltf(dir / "models" / "quads.gltf", s);
    try {
        loadScene(dir / "scene.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("materials[0].normalTexture: bad texture index 9"), std::string::npos)
            << e.what();
    }
    fs::remove_all(dir);
}

TEST(GltfMaterials, RaylabRenderExitsNonZeroOnAMissingImageAndPrintsWarnings) {
    const fs::path dir = scratch("cli");
    test::writeGltf(dir / "models" / "quads.gltf", fullSpec(dir / "models"));
    std::ofstream(dir / "scene.json") << R"({ "render": { "width": 8, "height": 8, "spp": 1 },
  "objects": [ { "type": "mesh", "file": "models/quads.gltf" } ] })";
    auto run = [&](std::string& err) {
        const std::string cmd = std::string("'") + RAYLAB_RENDER_EXE + "' '" + (dir / "scene.json").string() + "' -q -o '" +
                                (dir / "out.exr").string() + "' 2> '" + (dir / "err.txt").string() + "' > /dev/null";
        const int raw = std::system(cmd.c_str());
        std::ifstream in(dir / "err.txt");
        err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    };
    std::string err;
    EXPECT_EQ(run(err), 0) << err;
    EXPECT_NE(err.find("raylab-render: warning: "), std::string::npos) << err;
    EXPECT_NE(err.find("materials[0].alphaMode: BLEND is ignored"), std::string::npos) << err;
    fs::remove(dir / "models" / "emit.png");
    EXPECT_NE(run(err), 0);
    EXPECT_NE(err.find("objects[0].file: "), std::string::npos) << err;
    EXPECT_NE(err.find("materials[0].emissiveTexture: images[3] 'emit.png': cannot read: no such file"), std::string::npos)
        << err;
    fs::remove_all(dir);
}
