// Roughness, metallic, emission and specular textures through the whole path (scene keys → loader → GPU),
// each compared with renders whose materials say the same thing without a texture: a texture must
// change the image where it says and nowhere else. And glTF materials per primitive on the GPU.
#include "render/shader_variant.h"
#include "render_helpers.h"
#include "support/gl_test.h"
#include "support/gltf_writer.h"
#include "support/statistics.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_mattex_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// 8×8 PNG: left half `left`, right half `right` (rgb each).
void writeHalves(const fs::path& path, glm::u8vec3 left, glm::u8vec3 right) {
    std::vector<unsigned char> px;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const glm::u8vec3 c = x < 4 ? left : right;
            px.insert(px.end(), {c.r, c.g, c.b});
        }
    test::writePng(path, 8, 8, 3, px);
}

// A quad filling a 16×16 view (uv 0..1 over x -1..1; visible u in about [0.14, 0.86]), lit by a
// constant sky of radiance 1, one bounce. MATERIAL is the quad's material's body.
std::string quadScene(const std::string& material, int maxBounces = 1) {
    return R"({
  "camera": { "position": [0, 0, 2], "look_at": [0, 0, 0], "fov": 40 },
  "render": { "width": 16, "height": 16, "spp": 16, "max_bounces": )" +
           std::to_string(maxBounces) + R"(, "rr_depth": 100, "nee": false, "sampler": "independent", "tone_map": "clamp" },
  "sky": { "type": "constant", "color": 1 },
  "materials": { "m": )" + material + R"( },
  "objects": [ { "type": "mesh", "material": "m",
    "positions": [-1,-1,0, 1,-1,0, 1,1,0, -1,1,0], "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] } ] })";
}

Scene load(const fs::path& dir, const std::string& text) {
    std::ofstream(dir / "scene.json") << text;
    return loadScene(dir / "scene.json");
}

// Largest channel difference over the pixel columns [x0, x1).
float maxDifference(const Image& a, const Image& b, int x0, int x1) {
    float d = 0.0f;
    for (int y = 0; y < a.height; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a.rgb(x, y)[c] - b.rgb(x, y)[c]));
    return d;
}

// Columns well inside each half: texels 0–3 are the left half; the bilinear seam covers u in
// [0.4375, 0.5625], i.e. pixel columns 7 and 8.
constexpr int kLeftEnd = 6;
constexpr int kRightStart = 10;

} // namespace

class MaterialTexturesTest : public test::GlTest {};

TEST_F(MaterialTexturesTest, RoughnessTextureMakesAMirrorOnlyWhereItIsZero) {
    const fs::path dir = scratch("rough");
    writeHalves(dir / "rough.png", {0, 0, 0}, {255, 255, 255});
    // f0 1, albedo 0: a mirror returns the sky's 1 exactly; roughness 1 loses energy (GGX single
    // scattering, about 0.3–0.45 head on).
    const std::string body = R"({ "albedo": 0, "f0": 1, "roughness": 1)";
    const Scene textured = load(dir, quadScene(body + R"(, "roughness_texture": "rough.png" })"));
    EXPECT_NE(featureName(sceneFeatures(textured)).find("roughness-tex"), std::string::npos);
    const Image withTexture = test::render(textured);
    const Image rough = test::render(load(dir, quadScene(body + " }")));
    const Image mirror = test::render(load(dir, quadScene(R"({ "albedo": 0, "f0": 1, "roughness": 0 })")));
    EXPECT_LT(maxDifference(withTexture, mirror, 0, kLeftEnd), 1e-5f) << "left half: roughness 1 × 0 = mirror";
    EXPECT_LT(maxDifference(withTexture, rough, kRightStart, 16), 1e-5f) << "right half: roughness 1 × 1 unchanged";
    EXPECT_GT(maxDifference(rough, mirror, 0, 16), 0.3f) << "the two halves must differ visibly";
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, MetallicTextureTintsTheSpecularWhereItIsOne) {
    const fs::path dir = scratch("metal");
    writeHalves(dir / "metal.png", {0, 0, 0}, {0, 0, 255});   // metallic is read from blue
    // Base colour orange, glossy: metal half = f0 orange, albedo 0; dielectric half = f0 0.04,
    // albedo orange. Each half must equal the plain material that says so.
    const std::string common = R"("roughness": 0.3, "albedo": [1, 0.5, 0.1], "f0": 0.04)";
    const Scene textured =
        load(dir, quadScene("{ " + common + R"(, "metallic": 1, "metallic_texture": "metal.png" })"));
    EXPECT_NE(featureName(sceneFeatures(textured)).find("metallic-tex"), std::string::npos);
    const Image withTexture = test::render(textured);
    const Image dielectric = test::render(load(dir, quadScene("{ " + common + " }")));
    const Image metal = test::render(load(dir, quadScene(R"({ "roughness": 0.3, "albedo": 0, "f0": [1, 0.5, 0.1] })")));
    EXPECT_LT(maxDifference(withTexture, dielectric, 0, kLeftEnd), 1e-5f) << "left half: metallic 1 × 0";
    EXPECT_LT(maxDifference(withTexture, metal, kRightStart, 16), 1e-4f) << "right half: a tinted metal";
    EXPECT_GT(maxDifference(metal, dielectric, 0, 16), 0.1f);
    // Without a texture the metallic mix is baked on loading: the same image as the explicit metal.
    const Image baked = test::render(load(dir, quadScene("{ " + common + R"(, "metallic": 1 })")));
    EXPECT_LT(maxDifference(baked, metal, 0, 16), 1e-4f);
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, ConstantSpecularTextureRendersAsTheMaterialWithThatF0) {
    // f0 1 × a constant sRGB texel (255, 128, 64) is f0 = (1, decode(128), decode(64)): the same
    // BSDF at every hit as the plain material, so the same image up to float rounding (glossy, with
    // a diffuse base, so both lobes and the lobe choice see f0).
    const fs::path dir = scratch("spec_const");
    writeHalves(dir / "spec.png", {255, 128, 64}, {255, 128, 64});
    auto decode = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    const std::string common = R"("albedo": [0.2, 0.5, 0.3], "roughness": 0.4)";
    const Scene textured = load(dir, quadScene("{ " + common + R"(, "f0": 1, "specular_texture": "spec.png" })", 2));
    EXPECT_NE(featureName(sceneFeatures(textured)).find("specular-tex"), std::string::npos);
    const Image withTexture = test::render(textured);
    const std::string f0 = "[1, " + std::to_string(decode(128.0 / 255.0)) + ", " + std::to_string(decode(64.0 / 255.0)) + "]";
    const Image plain = test::render(load(dir, quadScene("{ " + common + R"(, "f0": )" + f0 + " }", 2)));
    EXPECT_LT(maxDifference(withTexture, plain, 0, 16), 1e-5f);
    const Image white = test::render(load(dir, quadScene("{ " + common + R"(, "f0": 1 })", 2)));
    EXPECT_GT(maxDifference(white, plain, 0, 16), 0.05f) << "the texture's colour must show";
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, SpecularTextureGivesEachHalfItsF0) {
    // A mirror (albedo 0, roughness 0) seen almost head on in a sky of 1 returns Schlick's F ≈ f0
    // (f90 = 1; (1 - cos θ)^5 < 1e-4 here). Red texels on the left half, blue on the right: each
    // half must equal the plain mirror of that f0, and show it.
    const fs::path dir = scratch("spec_halves");
    writeHalves(dir / "spec.png", {255, 0, 0}, {0, 0, 255});
    const Scene textured = load(dir, quadScene(R"({ "albedo": 0, "roughness": 0, "f0": 1, "specular_texture": "spec.png" })"));
    const Image image = test::render(textured);
    const Image red = test::render(load(dir, quadScene(R"({ "albedo": 0, "roughness": 0, "f0": [1, 0, 0] })")));
    const Image blue = test::render(load(dir, quadScene(R"({ "albedo": 0, "roughness": 0, "f0": [0, 0, 1] })")));
    EXPECT_LT(maxDifference(image, red, 0, kLeftEnd), 1e-5f) << "left half: f0 red";
    EXPECT_LT(maxDifference(image, blue, kRightStart, 16), 1e-5f) << "right half: f0 blue";
    for (int y = 0; y < 16; ++y) {
        EXPECT_NEAR(image.rgb(2, y).r, 1.0f, 1e-3f) << y;
        EXPECT_NEAR(image.rgb(2, y).b, 0.0f, 1e-3f) << y;
        EXPECT_NEAR(image.rgb(13, y).r, 0.0f, 1e-3f) << y;
        EXPECT_NEAR(image.rgb(13, y).b, 1.0f, 1e-3f) << y;
    }
    // Before the metallic mix: metallic 1 takes f0 from the base colour, whatever the texture says.
    const Image metal = test::render(load(dir, quadScene(
        R"({ "albedo": [0, 1, 0], "roughness": 0, "f0": 1, "metallic": 1, "specular_texture": "spec.png" })")));
    const Image green = test::render(load(dir, quadScene(R"({ "albedo": 0, "roughness": 0, "f0": [0, 1, 0] })")));
    EXPECT_LT(maxDifference(metal, green, 0, 16), 1e-5f);
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, DataTexturesAreReadLinearly) {
    // A roughness (and metallic) image of 8-bit 128 means 128/255 = 0.502, not its sRGB decoding
    // 0.216: the textured quad must equal the plain material with roughness 0.502 (metallic 0.502).
    const fs::path dir = scratch("linear");
    writeHalves(dir / "half.png", {128, 128, 128}, {128, 128, 128});
    const std::string common = R"("albedo": [0.9, 0.6, 0.3], "f0": 0.04)";
    const Image textured = test::render(load(dir, quadScene("{ " + common +
        R"(, "roughness": 1, "metallic": 1, "roughness_texture": "half.png", "metallic_texture": "half.png" })")));
    const std::string v = std::to_string(128.0 / 255.0);
    const Image plain = test::render(load(dir, quadScene("{ " + common + R"(, "roughness": )" + v + R"(, "metallic": )" + v + " }")));
    EXPECT_LT(maxDifference(textured, plain, 0, 16), 1e-4f);
    const std::string s = std::to_string(std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4));
    const Image srgb = test::render(load(dir, quadScene("{ " + common + R"(, "roughness": )" + s + R"(, "metallic": )" + s + " }")));
    EXPECT_GT(maxDifference(textured, srgb, 0, 16), 0.05f) << "the decodings must be told apart";
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, NormalScaleZeroFlattensTheNormalMap) {
    // A normal map tilting every normal (n = (0.6, 0, 0.8)) under a gradient sky changes the image;
    // normal_scale 0 keeps only its z: the flat quad's image.
    const fs::path dir = scratch("nscale");
    writeHalves(dir / "tilt.png", {204, 128, 230}, {204, 128, 230});
    auto scene = [&](const std::string& extra) {
        std::string text = quadScene(R"({ "albedo": 1)" + extra + " }");
        const std::string sky = R"("type": "constant", "color": 1)";
        text.replace(text.find(sky), sky.size(), R"("type": "gradient", "top": 1, "bottom": 0)");
        return load(dir, text);
    };
    const Image flat = test::render(scene(""));
    const Image tilted = test::render(scene(R"(, "normal_texture": "tilt.png")"));
    const Image scaled0 = test::render(scene(R"(, "normal_texture": "tilt.png", "normal_scale": 0)"));
    EXPECT_GT(maxDifference(flat, tilted, 0, 16), 0.05f);
    EXPECT_LT(maxDifference(flat, scaled0, 0, 16), 1e-5f);
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, EmissionTextureLightsOnlyWhereItIsNotZeroAndIsSrgbDecoded) {
    const fs::path dir = scratch("emit");
    writeHalves(dir / "emit.png", {0, 0, 0}, {128, 255, 64});
    // No bounces: the image is the emission alone. Right half: strength 2 × sRGB-decoded texel.
    const std::string body = R"({ "albedo": 0.5, "emission": [1, 1, 0.5], "strength": 2, "emission_texture": "emit.png" })";
    const Scene scene = load(dir, quadScene(body, 0));
    EXPECT_NE(featureName(sceneFeatures(scene)).find("emission-tex"), std::string::npos);
    const Image image = test::render(scene);
    auto decode = [](float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); };
    const glm::vec3 right(2.0f * decode(128.0f / 255.0f), 2.0f * 1.0f, 2.0f * 0.5f * decode(64.0f / 255.0f));
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < kLeftEnd; ++x) EXPECT_EQ(image.rgb(x, y), glm::vec3(0.0f)) << x << "," << y;
        for (int x = kRightStart; x < 16; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.rgb(x, y)[c], right[c], 1e-5f) << x << "," << y;
    }
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, TexturedEmitterIsLitByBsdfSamplesAloneWithNee) {
    // A floor lit by an emissive sphere whose emission texture covers half of it (u < 0.5): NEE
    // must skip that light (its radiance is not one number), and BSDF samples then count its light
    // fully, so the NEE and plain images agree. Had NEE sampled the sphere with the untextured
    // radiance, the NEE image would be much brighter. Fixed seeds; two-sided z-test at α = 0.01.
    const fs::path dir = scratch("nee");
    writeHalves(dir / "emit.png", {255, 255, 255}, {0, 0, 0});
    auto scene = [&](bool nee) {
        return load(dir, std::string(R"({
  "camera": { "position": [0, 3, 0.01], "look_at": [0, 0, 0], "fov": 60 },
  "render": { "width": 12, "height": 12, "spp": 128, "max_bounces": 1, "rr_depth": 100, "nee": )") +
                             (nee ? "true" : "false") + R"(, "seed": 7 },
  "sky": { "type": "constant", "color": 0 },
  "materials": { "floor": { "albedo": 0.8 },
                 "lamp": { "albedo": 0, "emission": 1, "strength": 8, "emission_texture": "emit.png" },
                 "bulb": { "albedo": 0, "emission": 1, "strength": 2 } },
  "objects": [ { "type": "mesh", "material": "floor", "positions": [-2,0,-2, 2,0,-2, 2,0,2, -2,0,2], "indices": [0,1,2, 0,2,3] },
               { "type": "sphere", "center": [0, 1, 0], "radius": 0.5, "material": "lamp" },
               { "type": "sphere", "center": [1.5, 0.3, 1.5], "radius": 0.1, "material": "bulb" } ] })");
    };
    const Image plain = test::render(scene(false));
    const Image nee = test::render(scene(true));
    // Paired per pixel: the pixels' differences have mean 0 when both estimate the same image
    // (each pixel has its own random stream, so the differences are independent).
    const std::vector<double> a = test::channel(plain, 1), b = test::channel(nee, 1);
    std::vector<double> d;
    for (std::size_t i = 0; i < a.size(); ++i) d.push_back(a[i] - b[i]);
    const double se = test::standardError(d);
    std::printf("floor lit by a textured emitter: plain %.4f, nee %.4f, standard error of the difference %.4f\n",
                test::mean(a), test::mean(b), se);
    EXPECT_LT(std::abs(test::mean(d)), 2.576 * se) << "plain " << test::mean(a) << " nee " << test::mean(b);
    EXPECT_GT(test::mean(a), 0.05) << "the floor must be lit";
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, SecondBounceAfterADiffuseBounceUsesACoarserLevelThanAfterAMirror) {
    // Camera → quad A (mirror, or diffuse white) → big textured quad B behind the camera, shown
    // in the mip-level view (blue 0, green 4, red 8+). After the mirror the cone keeps the pixel's
    // spread (level about 3: more blue than red); a diffuse bounce widens it by π/2 (ray_cone.glsl):
    // level about 6 (more red than blue). Without the widening both would look alike.
    const fs::path dir = scratch("cone");
    {
        std::vector<unsigned char> px(256 * 256 * 3, 200);
        test::writePng(dir / "fine.png", 256, 256, 3, px);
    }
    auto redMinusBlue = [&](const std::string& a) {
        const Scene scene = load(dir, R"({
  "camera": { "position": [0, 0, 2], "look_at": [0, 0, 0], "fov": 20 },
  "render": { "width": 16, "height": 16, "spp": 64, "max_bounces": 2, "rr_depth": 100, "show_mip_level": 1, "seed": 3 },
  "sky": { "type": "constant", "color": 1 },
  "materials": { "a": )" + a + R"(, "b": { "albedo": 1, "albedo_texture": "fine.png" } },
  "objects": [ { "type": "mesh", "material": "a", "positions": [-1,-1,0, 1,-1,0, 1,1,0, -1,1,0], "indices": [0,1,2, 0,2,3] },
               { "type": "mesh", "material": "b", "positions": [-10,-10,4, 10,-10,4, 10,10,4, -10,10,4], "indices": [0,1,2, 0,2,3],
                 "uvs": [0,0, 1,0, 1,1, 0,1] } ] })");
        const Image image = test::render(scene);
        return test::mean(test::channel(image, 0)) - test::mean(test::channel(image, 2));
    };
    const double mirror = redMinusBlue(R"({ "albedo": 0, "f0": 1, "roughness": 0 })");
    const double diffuse = redMinusBlue(R"({ "albedo": 1 })");
    std::printf("mean red - blue of the mip-level view: after a mirror %.3f, after a diffuse bounce %.3f\n", mirror, diffuse);
    EXPECT_LT(mirror, -0.05) << "after a mirror: a fine level (blue)";
    EXPECT_GT(diffuse, 0.05) << "after a diffuse bounce: a coarse level (red)";
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, WrapModesOnTheGpu) {
    // uv runs 0..2 across the quad (visible u about 0.27..1.73); the texture is black on its left
    // half, white on its right. Repeat shows the pattern twice, clamp stretches the white edge over
    // u > 1, mirror folds it back (white for u in (1, 1.5), black beyond).
    const fs::path dir = scratch("wrap");
    writeHalves(dir / "halves.png", {0, 0, 0}, {255, 255, 255});
    std::string text = quadScene(R"({ "albedo": 1, "albedo_texture": "halves.png" })");
    const std::string uvs = R"("uvs": [0,0, 1,0, 1,1, 0,1])";
    text.replace(text.find(uvs), uvs.size(), R"("uvs": [0,0, 2,0, 2,1, 0,1])");
    Scene scene = load(dir, text);
    auto valueAt = [&](TextureWrap mode, float u) {
        scene.textures[0].wrapU = mode;
        const Image image = test::render(scene);
        // The pixel column that holds this u (x = u - 1 in the world; the view spans ±0.728 over
        // 16 pixels); the probes keep a texel and a half away from the black/white seams, so the
        // trilinear taps of levels 0 and 1 all see one colour.
        const int px = int(std::floor(((u - 1.0f) / 0.728f + 1.0f) * 8.0f));
        return image.rgb(px, 8).g;
    };
    EXPECT_EQ(featureName(sceneFeatures(scene)).find("wrap-modes"), std::string::npos);
    EXPECT_NEAR(valueAt(TextureWrap::Repeat, 1.2f), 0.0f, 1e-5f);
    EXPECT_NEAR(valueAt(TextureWrap::Repeat, 1.65f), 1.0f, 1e-5f);
    EXPECT_NEAR(valueAt(TextureWrap::ClampToEdge, 1.2f), 1.0f, 1e-5f);
    EXPECT_NEAR(valueAt(TextureWrap::ClampToEdge, 1.65f), 1.0f, 1e-5f);
    EXPECT_NE(featureName(sceneFeatures(scene)).find("wrap-modes"), std::string::npos);
    EXPECT_NEAR(valueAt(TextureWrap::MirroredRepeat, 1.2f), 1.0f, 1e-5f);
    EXPECT_NEAR(valueAt(TextureWrap::MirroredRepeat, 1.65f), 0.0f, 1e-5f);
    EXPECT_NEAR(valueAt(TextureWrap::MirroredRepeat, 0.3f), 0.0f, 1e-5f) << "inside [0, 1) nothing changes";
    fs::remove_all(dir);
}

TEST_F(MaterialTexturesTest, GltfMaterialsPerPrimitiveOnTheGpu) {
    // Two quads from one glTF file: a red base-colour factor and a base-colour texture (sRGB 128
    // grey); in a constant sky of 1 with one bounce each shows its albedo. Metallic 0 keeps f0 0.04,
    // so compare with the JSON material that says the same.
    const fs::path dir = scratch("gltf");
    fs::create_directories(dir / "models");
    test::writePng(dir / "models" / "grey.png", 2, 2, 3, std::vector<unsigned char>(12, 128));
    test::GltfSpec s;
    s.primitiveMaterials = {0, 1};
    s.images = R"([ { "uri": "grey.png" } ])";
    s.textures = R"([ { "source": 0 } ])";
    s.materials = R"([ { "pbrMetallicRoughness": { "baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0, "roughnessFactor": 0.5 } },
                      { "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 }, "metallicFactor": 0, "roughnessFactor": 0.5 } } ])";
    test::writeGltf(dir / "models" / "two.gltf", s);
    const std::string view = R"(
  "camera": { "position": [0, 0, 3], "look_at": [0, 0, 0], "fov": 30 },
  "render": { "width": 16, "height": 8, "spp": 16, "max_bounces": 1, "rr_depth": 100, "seed": 5, "nee": false,
              "sampler": "independent" },
  "sky": { "type": "constant", "color": 1 },)";
    const Image gltf = test::render(load(dir, "{" + view + R"(
  "objects": [ { "type": "mesh", "file": "models/two.gltf" } ] })"));
    const float grey = std::pow((128.0f / 255.0f + 0.055f) / 1.055f, 2.4f);
    const Image json = test::render(load(dir, "{" + view + R"(
  "materials": { "red": { "albedo": [1, 0, 0], "f0": 0.04, "roughness": 0.5 },
                 "grey": { "albedo": )" + std::to_string(grey) + R"(, "f0": 0.04, "roughness": 0.5 } },
  "objects": [ { "type": "mesh", "material": "red", "positions": [-1,-0.5,0, 0,-0.5,0, 0,0.5,0, -1,0.5,0], "indices": [0,1,2, 0,2,3] },
               { "type": "mesh", "material": "grey", "positions": [0,-0.5,0, 1,-0.5,0, 1,0.5,0, 0,0.5,0], "indices": [0,1,2, 0,2,3] } ] })"));
    EXPECT_LT(maxDifference(gltf, json, 0, 16), 1e-4f);
    EXPECT_GT(gltf.rgb(3, 4).r, 2.0f * gltf.rgb(3, 4).g) << "left quad red";
    fs::remove_all(dir);
}
