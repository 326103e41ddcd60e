// sky.type "map" on the GPU: a uniform map is the constant sky (the furnace stays exact), the
// image's orientation and sky.rotation, and the loader's errors for sky.map.
#include "render_helpers.h"
#include "support/gl_test.h"

#include <OpenImageIO/imageio.h>
#include "support/scene_errors.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

class EnvironmentMapTest : public test::GlTest {};

// Writes a W × H float RGB image whose value at texel (x, y) is value(u, v) of the texel centre.
fs::path writeMap(const std::string& name, int w, int h, const std::function<float(float, float)>& value) {
    const fs::path dir = fs::temp_directory_path() / "raylab_envmap_test";
    fs::create_directories(dir);
    const fs::path file = dir / name;
    std::vector<float> px(size_t(w * h * 3));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                px[size_t((y * w + x) * 3 + c)] = value((float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h));
    auto out = OIIO::ImageOutput::create(file.string());
    EXPECT_TRUE(out && out->open(file.string(), OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT)) &&
                out->write_image(OIIO::TypeDesc::FLOAT, px.data()) && out->close());
    return file;
}

std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
    return test::sceneErrorOf(text, overrides, "m.json", "");
}

} // namespace

TEST_F(EnvironmentMapTest, UniformMapKeepsTheFurnaceExact) {
    const fs::path map = writeMap("uniform.exr", 16, 8, [](float, float) { return 1.0f; });
    const Scene scene = loadScene(test::scenePath("furnace.json"),
                                  {"render.width=16", "render.height=16", "sky.type=map",
                                   "sky.map=\"" + map.string() + "\"", "sky.rotation=33"});
    const Image img = test::render(scene);
    for (size_t i = 0; i < img.rgba.size(); ++i)
        if (i % 4 != 3) {
            ASSERT_EQ(img.rgba[i], 0.5f) << i;
        }
}

TEST_F(EnvironmentMapTest, CentreOfTheImageIsAheadAndRotationTurnsIt) {
    // Bright only in the middle half of the image's width (u in [0.25, 0.75)): the camera
    // looking along -z sees it; turned by 180 degrees it sees the dark half.
    const fs::path map = writeMap("front.exr", 64, 32, [](float u, float) { return u >= 0.25f && u < 0.75f ? 2.0f : 0.0f; });
    const std::string text = R"({
      "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 30 },
      "render": { "width": 8, "height": 8, "spp": 4, "max_bounces": 0 },
      "sky": { "type": "map", "map": ")" + map.string() + R"(" },
      "objects": [ { "center": [0, 0, 50], "radius": 1 } ] })";
    const Image ahead = test::render(parseScene(text, "front.json"));
    const Image behind = test::render(parseScene(text, "front.json", {"sky.rotation=180"}));
    const Image strength = test::render(parseScene(text, "front.json", {"sky.strength=0.5"}));
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            EXPECT_EQ(ahead.rgb(x, y).x, 2.0f);
            EXPECT_EQ(behind.rgb(x, y).x, 0.0f);
            EXPECT_EQ(strength.rgb(x, y).x, 1.0f);
        }
}

TEST(EnvironmentMapKeys, MissingFilesAndMissingMapsAreLocatedErrors) {
    EXPECT_EQ(errorOf(R"({ "sky": { "type": "map", "map": "nope.hdr" }, "objects": [ {} ] })"),
              "m.json:1:34: error: sky.map: cannot read 'nope.hdr': no such file");
    EXPECT_EQ(errorOf(R"({ "sky": { "type": "map" }, "objects": [ {} ] })"),
              "m.json:1:20: error: sky.type: 'map' needs sky.map, an equirectangular .hdr or .exr image");
    EXPECT_EQ(errorOf(R"({ "sky": { "map": 3 }, "objects": [ {} ] })"),
              "m.json:1:19: error: sky.map: expected an image file name (a non-empty string), got number");
    EXPECT_EQ(errorOf(R"({ "objects": [ {} ] })", {"sky.type=map"}),
              "--set sky.type=map: error: sky.type: 'map' needs sky.map, an equirectangular .hdr or .exr image");
}

TEST(EnvironmentMapKeys, MapPathsAreRelativeToTheSceneFile) {
    const Scene s = loadScene(test::scenePath("environment.json"));
    EXPECT_EQ(s.sky.type, Sky::Type::Map);
    EXPECT_EQ(s.sky.map, fs::path(test::scenePath("sky_procedural.hdr")));
}
