// Baked ambient-occlusion maps (glTF occlusionTexture, the scene's occlusion_texture): loaded into
// the texture atlas only when a material has one, shown by the baked-ao view as 1 + strength ×
// (red − 1), and never part of the path-traced image.
#include "render_helpers.h"
#include "support/debug_view_render.h"
#include "support/gl_test.h"
#include "support/gltf_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

class BakedOcclusionTest : public test::GlTest {
protected:
    void SetUp() override {
        test::GlTest::SetUp();
        dir_ = fs::temp_directory_path() / ("raylab_baked_ao_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "models");
        // 8×8 texels, a quadrant each: red 0, 64, 128 and 255 (top-left, top-right, bottom-left,
        // bottom-right); green 200 everywhere, so a view reading green would show it.
        std::vector<unsigned char> px;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) px.insert(px.end(), {kRed[y < 4 ? 0 : 1][x < 4 ? 0 : 1], 200, 90});
        test::writePng(dir_ / "models" / "ao.png", 8, 8, 3, px);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
        test::GlTest::TearDown();
    }

    // A unit quad in z = 0 facing a camera that sees only it; its glTF material has the map (with
    // strength 0.5) or not.
    Scene gltfScene(bool withMap) const {
        test::GltfSpec s;
        s.translateX = 0.5f;
        s.images = R"([ { "uri": "ao.png" } ])";
        s.textures = R"([ { "source": 0 } ])";
        s.materials = std::string(R"([ { "pbrMetallicRoughness": { "baseColorFactor": [0.6, 0.5, 0.4, 1], "metallicFactor": 0,
                                                                    "roughnessFactor": 0.5 })") +
                      (withMap ? R"(, "occlusionTexture": { "index": 0, "strength": 0.5 })" : "") + " } ]";
        test::writeGltf(dir_ / "models" / "quad.gltf", s);
        return load(R"("objects": [ { "type": "mesh", "file": "models/quad.gltf" } ])");
    }

    // The same quad inline, its JSON material naming the map.
    Scene jsonScene() const {
        return load(R"("materials": { "m": { "albedo": [0.6, 0.5, 0.4], "occlusion_texture": "models/ao.png", "occlusion_strength": 0.5 } },
                       "objects": [ { "type": "mesh", "material": "m", "positions": [-0.5,-0.5,0, 0.5,-0.5,0, 0.5,0.5,0, -0.5,0.5,0],
                                      "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] } ])");
    }

    Scene load(const std::string& objects) const {
        std::ofstream(dir_ / "scene.json") << R"({
          "camera": { "position": [0, 0, 2], "look_at": [0, 0, 0], "fov": 20 },
          "render": { "width": 16, "height": 16, "spp": 4, "max_bounces": 3, "sampler": "independent" },
          "sky": { "type": "constant", "color": 1 }, )" << objects << " }";
        return loadScene(dir_ / "scene.json");
    }

    static Image bakedView(const Scene& s) { return test::renderView(s, DebugView::BakedAo); }

    static constexpr unsigned char kRed[2][2] = {{0, 64}, {128, 255}};
    fs::path dir_;
};

TEST_F(BakedOcclusionTest, AGltfOcclusionMapIsKeptWithoutAWarning) {
    const Scene with = gltfScene(true);
    ASSERT_EQ(with.materials.size(), 2u);   // "default", then the file's
    const Material& m = with.materials[1];
    ASSERT_GE(m.occlusionTextureIndex, 0);
    EXPECT_FLOAT_EQ(m.occlusionStrength, 0.5f);
    EXPECT_EQ(with.textures.size(), 1u);
    for (const std::string& w : with.warnings) EXPECT_EQ(w.find("occlusion"), std::string::npos) << w;
    EXPECT_TRUE(gltfScene(false).textures.empty()) << "no map, nothing in the atlas";
}

TEST_F(BakedOcclusionTest, TheBakedViewShowsOnePlusStrengthTimesTexelMinusOne) {
    for (const bool gltf : {true, false}) {
        SCOPED_TRACE(gltf ? "glTF occlusionTexture" : "scene occlusion_texture");
        const Image im = bakedView(gltf ? gltfScene(true) : jsonScene());
        // The quad spans ±0.5, the view ±0.35: pixels 3-4 and 11-12 lie a texel and more inside a
        // quadrant, so every bilinear tap of the magnified map reads that quadrant's texels.
        for (int qy = 0; qy < 2; ++qy)
            for (int qx = 0; qx < 2; ++qx) {
                const float expected = 1.0f + 0.5f * (float(kRed[qy][qx]) / 255.0f - 1.0f);
                for (int y : {3 + 8 * qy, 4 + 8 * qy})
                    for (int x : {3 + 8 * qx, 4 + 8 * qx}) {
                        const glm::vec3 c = im.rgb(x, y);
                        EXPECT_NEAR(c.x, expected, 1e-5f) << x << ", " << y;
                        EXPECT_EQ(c.x, c.y);
                        EXPECT_EQ(c.x, c.z);
                    }
            }
    }
    const Image none = bakedView(gltfScene(false));
    EXPECT_EQ(none.rgb(3, 3), glm::vec3(1.0f)) << "a material without a map shows white";
}

TEST_F(BakedOcclusionTest, TheRenderIsBitIdenticalWithAndWithoutTheMap) {
    const Image with = test::render(gltfScene(true));
    const Image without = test::render(gltfScene(false));
    ASSERT_EQ(with.rgba.size(), without.rgba.size());
    EXPECT_EQ(with.rgba, without.rgba) << "the path tracer never reads the map";
    EXPECT_NE(with.rgba, bakedView(gltfScene(true)).rgba) << "and the render is not the baked view";
}

} // namespace
