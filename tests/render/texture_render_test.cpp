// Image textures through the whole path: a scene file names a PNG, the loader reads it, the GPU
// samples it at the hit's uv.
#include "render_helpers.h"
#include "support/gl_test.h"
#include "support/statistics.h"

#include <OpenImageIO/imageio.h>

#include <array>

#include <filesystem>
#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

// 8×8 RGB PNG, top row first as files store it: blue | white over red | green.
void writeQuadrantsPng(const fs::path& path) {
    std::vector<unsigned char> px;
    for (int row = 0; row < 8; ++row)
        for (int x = 0; x < 8; ++x) {
            const bool top = row < 4, left = x < 4;
            const unsigned char r = (!top && left) || (top && !left) ? 255 : 0;
            const unsigned char g = (!top && !left) || (top && !left) ? 255 : 0;
            const unsigned char b = top ? 255 : 0;
            px.insert(px.end(), {r, g, b});
        }
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(8, 8, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
}

fs::path scratch() {
    const fs::path dir = fs::temp_directory_path() / ("raylab_texture_test_" + std::to_string(::getpid()));
    fs::create_directories(dir / "textures");
    return dir;
}

constexpr const char* kQuadScene = R"({
  "camera": { "position": [0, 0, 2], "look_at": [0, 0, 0], "fov": 40 },
  "render": { "width": 16, "height": 16, "spp": 4, "max_bounces": 1, "rr_depth": 100, "tone_map": "clamp" },
  "sky": { "type": "constant", "color": 1 },
  "materials": { "checker": { "albedo": 1, "albedo_texture": "textures/quadrants.png" } },
  "objects": [ { "type": "mesh", "material": "checker",
    "positions": [-1,-1,0, 1,-1,0, 1,1,0, -1,1,0], "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] } ] })";

} // namespace

class TextureRenderTest : public test::GlTest {};

TEST_F(TextureRenderTest, UvCheckerLandsWhereExpectedOnAQuad) {
    const fs::path dir = scratch();
    writeQuadrantsPng(dir / "textures" / "quadrants.png");
    std::ofstream(dir / "quad.json") << kQuadScene;
    const Scene scene = loadScene(dir / "quad.json");
    ASSERT_EQ(scene.textures.size(), 1u);
    // The quad fills the view (it spans ±1 at distance 2; the view ±0.73). One bounce reaches the
    // sky (radiance 1), so a pixel is exactly the texture's linear colour there.
    const Image image = test::render(scene);
    // Pixel centres well inside each quadrant (away from the bilinear seams), image top row first.
    const struct { int x, y; glm::vec3 colour; } probes[] = {
        {3, 3, {0, 0, 1}}, {12, 3, {1, 1, 1}}, {3, 12, {1, 0, 0}}, {12, 12, {0, 1, 0}}};
    for (const auto& p : probes)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(image.rgb(p.x, p.y)[c], p.colour[c], 1e-5f) << p.x << "," << p.y << " channel " << c;
    fs::remove_all(dir);
}

TEST_F(TextureRenderTest, MissingAndBrokenImagesAreLocatedErrors) {
    const fs::path dir = scratch();
    std::ofstream(dir / "quad.json") << kQuadScene;
    try {
        loadScene(dir / "quad.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "quad.json").string() +
                                             ":5:62: error: materials.checker.albedo_texture: " +
                                             (dir / "textures" / "quadrants.png").string() +
                                             ": cannot read: no such file");
    }
    std::ofstream(dir / "textures" / "quadrants.png") << "not a png";
    try {
        loadScene(dir / "quad.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("materials.checker.albedo_texture: " +
                                             (dir / "textures" / "quadrants.png").string() + ": "),
                  std::string::npos)
            << e.what();
    }
    fs::remove_all(dir);
}

TEST_F(TextureRenderTest, ManyTexturesOfDifferentSizes) {
    // Two quads side by side, each with its own texture (5×3 magenta, 2×7 cyan: odd sizes, so
    // every mip level has a different shape), plus the 8×8 one unused by any object: each quad
    // must find its own texels in the shared buffer.
    const fs::path dir = scratch();
    auto uniform = [&](const std::string& name, int w, int h, std::array<unsigned char, 3> rgb) {
        std::vector<unsigned char> px;
        for (int i = 0; i < w * h; ++i) px.insert(px.end(), rgb.begin(), rgb.end());
        auto out = OIIO::ImageOutput::create((dir / "textures" / name).string());
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open((dir / "textures" / name).string(), OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
        out->close();
    };
    writeQuadrantsPng(dir / "textures" / "quadrants.png");
    uniform("magenta.png", 5, 3, {255, 0, 255});
    uniform("cyan.png", 2, 7, {0, 255, 255});
    std::ofstream(dir / "two.json") << R"({
      "camera": { "position": [0, 0, 2], "look_at": [0, 0, 0], "fov": 40 },
      "render": { "width": 16, "height": 16, "spp": 4, "max_bounces": 1, "rr_depth": 100, "tone_map": "clamp" },
      "sky": { "type": "constant", "color": 1 },
      "materials": { "a": { "albedo": 1, "albedo_texture": "textures/quadrants.png" },
                     "b": { "albedo": 1, "albedo_texture": "textures/magenta.png" },
                     "c": { "albedo": [1, 0.5, 1], "albedo_texture": "textures/cyan.png" } },
      "objects": [
        { "type": "mesh", "material": "b", "positions": [-1,-1,0, 0,-1,0, 0,1,0, -1,1,0],
          "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] },
        { "type": "mesh", "material": "c", "positions": [0,-1,0, 1,-1,0, 1,1,0, 0,1,0],
          "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] },
        { "type": "sphere", "center": [0, 0, 50], "radius": 1, "material": "a" } ] })";
    const Scene scene = loadScene(dir / "two.json");
    ASSERT_EQ(scene.textures.size(), 3u);
    const Image image = test::render(scene);
    for (int y : {2, 8, 13}) {
        EXPECT_NEAR(image.rgb(3, y)[0], 1.0f, 1e-5f);
        EXPECT_NEAR(image.rgb(3, y)[1], 0.0f, 1e-5f);
        EXPECT_NEAR(image.rgb(3, y)[2], 1.0f, 1e-5f);
        EXPECT_NEAR(image.rgb(12, y)[0], 0.0f, 1e-5f);
        EXPECT_NEAR(image.rgb(12, y)[1], 0.5f, 1e-5f) << "albedo multiplies the texture";
        EXPECT_NEAR(image.rgb(12, y)[2], 1.0f, 1e-5f);
    }
    fs::remove_all(dir);
}

TEST_F(TextureRenderTest, NormalMapChangesShadingAsPredicted) {
    // A quad facing the camera (+z) under a sky whose radiance is (d.y + 1) / 2, albedo 1, one
    // bounce. A normal map tilting every normal towards +v (= +y) by asin 0.6 makes the cosine
    // lobe look up: the pixel value is ∫ cosθ'/π · [d.z > 0] · (d.y + 1)/2 dω around the tilted
    // normal (directions under the quad end the path), integrated numerically here.
    const fs::path dir = scratch();
    {
        std::vector<float> px;
        for (int i = 0; i < 4 * 4; ++i) px.insert(px.end(), {0.5f, 0.8f, 0.9f});   // n = (0, 0.6, 0.8)
        auto out = OIIO::ImageOutput::create((dir / "textures" / "tilt.exr").string());
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open((dir / "textures" / "tilt.exr").string(), OIIO::ImageSpec(4, 4, 3, OIIO::TypeDesc::FLOAT)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        out->close();
    }
    std::ofstream(dir / "nm.json") << R"({
      "camera": { "position": [0, 0, 2], "look_at": [0, 0, 0], "fov": 40 },
      "render": { "width": 16, "height": 16, "spp": 256, "max_bounces": 1, "rr_depth": 100, "tone_map": "clamp" },
      "sky": { "type": "gradient", "top": 1, "bottom": 0 },
      "materials": { "bumpy": { "albedo": 1, "normal_texture": "textures/tilt.exr" } },
      "objects": [ { "type": "mesh", "material": "bumpy",
        "positions": [-1,-1,0, 1,-1,0, 1,1,0, -1,1,0], "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] } ] })";
    const Scene scene = loadScene(dir / "nm.json");
    const Image image = test::render(scene);
    // Prediction: midpoint rule over (θ', φ') around n = (0, 0.6, 0.8).
    const glm::dvec3 n(0.0, 0.6, 0.8), t(1.0, 0.0, 0.0), b = glm::cross(n, t);
    double expected = 0.0;
    const int steps = 1000;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const double th = (i + 0.5) * (M_PI / 2) / steps, ph = (j + 0.5) * 2 * M_PI / steps;
            const glm::dvec3 d = std::sin(th) * std::cos(ph) * t + std::sin(th) * std::sin(ph) * b + std::cos(th) * n;
            if (d.z <= 0.0) continue;
            expected += std::cos(th) / M_PI * (d.y + 1.0) / 2.0 * std::sin(th) * (M_PI / 2 / steps) * (2 * M_PI / steps);
        }
    const std::vector<double> v = test::channel(image, 1);
    const double m = test::mean(v), se = test::standardError(v);
    EXPECT_NEAR(m, expected, 4.0 * se) << "expected " << expected;
    EXPECT_GT(expected - 0.5, 20.0 * se) << "the map must make a visible difference from the flat 0.5";
    fs::remove_all(dir);
}
