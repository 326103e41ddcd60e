// glTF KHR_materials_specular (and KHR_materials_ior's ior) onto raylab's f0 and specular_texture
// (the table in scenes/FORMAT.md): factors alone give f0, textures are baked per texel into one
// specular_texture under f0 1, the extensions count as supported, and a malformed value is an
// error at its place in the file. The assets are generated here.
#include "scene/gltf_loader.h"
#include "scene/scene_loader.h"
#include "support/gltf_writer.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_gltf_specular_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "models");
    return dir;
}

float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

// 2 × 2 images, top row first as in the file: a colour (RGB) and a strength (alpha) per texel.
const unsigned char kColour[4][3] = {{255, 0, 128}, {64, 255, 255}, {200, 100, 50}, {0, 0, 0}};
const unsigned char kStrength[4] = {255, 128, 0, 64};

Scene loadQuads(const fs::path& dir, const test::GltfSpec& s) {
    test::writeGltf(dir / "models" / "quads.gltf", s);
    std::ofstream(dir / "scene.json") << R"({ "objects": [ { "type": "mesh", "file": "models/quads.gltf" } ] })";
    return loadScene(dir / "scene.json");
}

const Material& gltfMaterial(const Scene& scene, int k) {
    const std::string prefix = "models/quads.gltf#materials[" + std::to_string(k) + "]";
    for (const Material& m : scene.materials)
        if (m.name.rfind(prefix, 0) == 0) return m;
    throw std::runtime_error("no material " + prefix);
}

// The error loading `materials` (one material on one quad) gives, or "" when it loads.
std::string loadError(const fs::path& dir, const std::string& materials) {
    test::GltfSpec s;
    s.materials = materials;
    try {
        loadQuads(dir, s);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(GltfSpecular, FactorsGiveTheDielectricF0OfTheExtension) {
    const fs::path dir = scratch("factors");
    test::GltfSpec s;
    s.primitiveMaterials = {0, 1, 2};
    s.extensionsUsed = R"(["KHR_materials_specular", "KHR_materials_ior"])";
    s.materials = R"([
      { "extensions": { "KHR_materials_specular": { "specularFactor": 0.5, "specularColorFactor": [2, 1, 30] } } },
      { "extensions": { "KHR_materials_specular": { "specularColorFactor": [0.5, 1, 1.5] }, "KHR_materials_ior": { "ior": 2 } } },
      { "extensions": { "KHR_materials_ior": { "ior": 1.33 } } } ])";
    const Scene scene = loadQuads(dir, s);
    // f0 = min(((ior - 1) / (ior + 1))^2 x specularColorFactor, 1) x specularFactor, ior 1.5 by default.
    const Material& a = gltfMaterial(scene, 0);
    EXPECT_FLOAT_EQ(a.f0.r, 0.04f * 2.0f * 0.5f);
    EXPECT_FLOAT_EQ(a.f0.g, 0.04f * 0.5f);
    EXPECT_FLOAT_EQ(a.f0.b, 0.5f) << "0.04 x 30 is clamped to 1 before the factor";
    EXPECT_EQ(a.specularTextureIndex, -1);
    const Material& b = gltfMaterial(scene, 1);
    const float f0Ior2 = (1.0f / 3.0f) * (1.0f / 3.0f);
    EXPECT_NEAR(b.f0.r, f0Ior2 * 0.5f, 1e-6f);
    EXPECT_NEAR(b.f0.g, f0Ior2, 1e-6f);
    EXPECT_NEAR(b.f0.b, f0Ior2 * 1.5f, 1e-6f);
    const float water = (0.33f / 2.33f) * (0.33f / 2.33f);
    EXPECT_NEAR(gltfMaterial(scene, 2).f0.r, water, 1e-6f) << "KHR_materials_ior alone sets the dielectric f0";
    fs::remove_all(dir);
}

TEST(GltfSpecular, TexturesAreBakedPerTexelIntoTheSpecularTexture) {
    const fs::path dir = scratch("textures");
    std::vector<unsigned char> colour, strength;
    for (int i = 0; i < 4; ++i) {
        colour.insert(colour.end(), kColour[i], kColour[i] + 3);
        strength.insert(strength.end(), {17, 34, 51, kStrength[i]});   // RGB must be ignored
    }
    test::writePng(dir / "models" / "colour.png", 2, 2, 3, colour);
    test::writePng(dir / "models" / "strength.png", 2, 2, 4, strength);
    test::GltfSpec s;
    s.images = R"([ { "uri": "colour.png" }, { "uri": "strength.png" } ])";
    s.textures = R"([ { "source": 0 }, { "source": 1 } ])";
    s.materials = R"([ { "extensions": { "KHR_materials_specular": { "specularFactor": 0.75,
        "specularColorFactor": [10, 20, 5], "specularColorTexture": { "index": 0 }, "specularTexture": { "index": 1 } } } } ])";
    const Scene scene = loadQuads(dir, s);
    const Material& m = gltfMaterial(scene, 0);
    EXPECT_EQ(m.f0, glm::vec3(1.0f)) << "f0 1: the texture is the f0";
    ASSERT_GE(m.specularTextureIndex, 0);
    const MipLevel& level = scene.textures.at(std::size_t(m.specularTextureIndex)).levels.at(0);
    ASSERT_EQ(level.width, 2);
    ASSERT_EQ(level.height, 2);
    const glm::vec3 factor(10.0f, 20.0f, 5.0f);
    for (int i = 0; i < 4; ++i) {
        // File texel i (top row first) is texel (i % 2, 1 - i / 2) of the level (row 0 = v 0, the bottom).
        const glm::vec4 got = level.texels[std::size_t((1 - i / 2) * 2 + i % 2)];
        for (int c = 0; c < 3; ++c) {
            const float expected =
                std::min(0.04f * factor[c] * srgbToLinear(float(kColour[i][c]) / 255.0f), 1.0f) * 0.75f * float(kStrength[i]) / 255.0f;
            EXPECT_NEAR(got[c], expected, 1e-5f) << "texel " << i << ", channel " << c;
        }
    }
    // Only the baked texture reaches the scene, not the two it was made of.
    EXPECT_EQ(scene.textures.size(), 1u);
    fs::remove_all(dir);
}

TEST(GltfSpecular, TheExtensionsAreSupportedWhenRequired) {
    const fs::path dir = scratch("required");
    test::GltfSpec s;
    s.materials = R"([ { "extensions": { "KHR_materials_specular": { "specularFactor": 0.5 } } } ])";
    std::string json = test::gltfJson(s, test::gltfBuffer(s, false), false);
    json.insert(1, R"( "extensionsRequired": ["KHR_materials_specular", "KHR_materials_ior", "KHR_texture_transform"],)");
    std::ofstream(dir / "models" / "quads.gltf") << json;
    const GltfAsset asset = loadGltfAsset(dir / "models" / "quads.gltf");
    ASSERT_EQ(asset.warnings.size(), 1u);
    EXPECT_NE(asset.warnings[0].find("KHR_texture_transform is not supported"), std::string::npos) << asset.warnings[0];
    fs::remove_all(dir);
}

TEST(GltfSpecular, MalformedValuesAreErrorsAtTheirPlace) {
    const fs::path dir = scratch("errors");
    const std::string file = (dir / "models" / "quads.gltf").string();
    const std::string ext = "materials[0].extensions.KHR_materials_specular.";
    const std::string at = (dir / "scene.json").string() + ":1:42: error: objects[0].file: " + file + ": ";
    EXPECT_EQ(loadError(dir, R"([ { "extensions": { "KHR_materials_specular": { "specularFactor": "high" } } } ])"),
              at + ext + "specularFactor: must be a number in [0, 1]");
    EXPECT_EQ(loadError(dir, R"([ { "extensions": { "KHR_materials_specular": { "specularFactor": 1.5 } } } ])"),
              at + ext + "specularFactor: must be a number in [0, 1]");
    EXPECT_EQ(loadError(dir, R"([ { "extensions": { "KHR_materials_specular": { "specularColorFactor": [1, 2] } } } ])"),
              at + ext + "specularColorFactor: must be three numbers >= 0");
    EXPECT_EQ(loadError(dir, R"([ { "extensions": { "KHR_materials_specular": { "specularColorFactor": [1, -2, 1] } } } ])"),
              at + ext + "specularColorFactor: must be three numbers >= 0");
    EXPECT_EQ(loadError(dir, R"([ { "extensions": { "KHR_materials_specular": { "specularTexture": { "index": 7 } } } } ])"),
              at + ext + "specularTexture.index: 7 is not a texture (0 in the file)");
    EXPECT_EQ(loadError(dir, R"([ { "extensions": { "KHR_materials_specular": { "specularColorTexture": 3 } } } ])"),
              at + ext + "specularColorTexture: expected a texture reference {\"index\": k}");
    EXPECT_EQ(loadError(dir, R"([ { "extensions": { "KHR_materials_ior": { "ior": 0.5 } } } ])"),
              at + "materials[0].extensions.KHR_materials_ior.ior: must be a number >= 1");
    EXPECT_EQ(loadError(dir, R"([ { "extensions": { "KHR_materials_specular": { "specularFactor": 0.5 } } } ])"), "");
    fs::remove_all(dir);
}
