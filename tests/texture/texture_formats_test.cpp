// Every image format the texture loader promises (texture.h: PNG, JPEG, EXR, HDR, TIFF): tiny
// files written here through OpenImageIO, named by a scene file, loaded by the scene loader, and
// their texels checked. PNG and EXR are also covered through the GPU (render/texture_render_test).
#include "scene/scene_loader.h"
#include "texture/texture.h"
#include "shaders/include/tone_map.glsl"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

constexpr int kSize = 32;   // pixels on a side: 2 × 2 flat blocks of 16 × 16

// The colour of block (bx, by) of the test images, as 8-bit codes; by counts from the file's top row.
std::array<int, 3> blockCode(int bx, int by) {
    static const std::array<int, 3> codes[4] = {{200, 40, 30}, {30, 170, 60}, {40, 60, 190}, {128, 128, 128}};
    return codes[by * 2 + bx];
}
// The linear float value of block (bx, by) in the float formats (HDR, float TIFF).
std::array<float, 3> blockValue(int bx, int by) {
    static const std::array<float, 3> values[4] = {{4.0f, 0.5f, 0.25f}, {0.125f, 2.0f, 1.0f}, {0.75f, 0.375f, 6.0f},
                                                   {1.5f, 1.5f, 1.5f}};
    return values[by * 2 + bx];
}

void writeFile(const fs::path& path, OIIO::TypeDesc type, const void* pixels, int quality = 0) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out) << path;
    OIIO::ImageSpec spec(kSize, kSize, 3, type);
    if (quality > 0) spec.attribute("CompressionQuality", quality);
    ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, pixels)) << out->geterror();
    out->close();
}

void writeCodes(const fs::path& path, int quality = 0) {
    std::vector<unsigned char> px;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c : blockCode(x / 16, y / 16)) px.push_back((unsigned char)c);
    writeFile(path, OIIO::TypeDesc::UINT8, px.data(), quality);
}

void writeValues(const fs::path& path) {
    std::vector<float> px;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (float v : blockValue(x / 16, y / 16)) px.push_back(v);
    writeFile(path, OIIO::TypeDesc::FLOAT, px.data());
}

// The texel at file pixel (x, y) (top row first) of the albedo texture of material `name`.
glm::vec4 texel(const Scene& scene, const std::string& name, int x, int y) {
    for (const Material& m : scene.materials)
        if (m.name == name) {
            const MipLevel& level = scene.textures.at(std::size_t(m.albedoTextureIndex)).levels[0];
            EXPECT_EQ(level.width, kSize);
            EXPECT_EQ(level.height, kSize);
            return level.texels[std::size_t(kSize - 1 - y) * std::size_t(kSize) + std::size_t(x)];   // row 0 = v 0
        }
    ADD_FAILURE() << "no material " << name;
    return glm::vec4(0.0f);
}

} // namespace

TEST(TextureFormats, JpegTiffAndHdrLoadThroughTheSceneFile) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_texture_formats_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    writeCodes(dir / "blocks.jpg", 100);
    writeCodes(dir / "blocks.tif");
    writeValues(dir / "blocks_float.tif");
    writeValues(dir / "blocks.hdr");
    std::ofstream(dir / "formats.json") << R"({ "materials": {
        "jpeg": { "albedo_texture": "blocks.jpg" }, "tiff": { "albedo_texture": "blocks.tif" },
        "tiff_float": { "albedo_texture": "blocks_float.tif" }, "hdr": { "albedo_texture": "blocks.hdr" } },
      "objects": [ { "type": "sphere", "material": "jpeg" }, { "type": "sphere", "material": "tiff" },
                   { "type": "sphere", "material": "tiff_float" }, { "type": "sphere", "material": "hdr" } ] })";
    const Scene scene = loadScene(dir / "formats.json");
    ASSERT_EQ(scene.textures.size(), 4u);
    // Probes: every block's centre region (4 pixels from its edges, clear of JPEG's chroma
    // upsampling, which blends across the 16 × 16 blocks' borders) and one pixel per corner.
    int probes = 0;
    for (int by = 0; by < 2; ++by)
        for (int bx = 0; bx < 2; ++bx)
            for (int y = 16 * by + 4; y < 16 * by + 12; ++y)
                for (int x = 16 * bx + 4; x < 16 * bx + 12; ++x) {
                    ++probes;
                    const std::array<int, 3> code = blockCode(bx, by);
                    const std::array<float, 3> value = blockValue(bx, by);
                    const glm::vec4 jpeg = texel(scene, "jpeg", x, y), tiff = texel(scene, "tiff", x, y);
                    const glm::vec4 tiffFloat = texel(scene, "tiff_float", x, y), hdr = texel(scene, "hdr", x, y);
                    const float hdrMax = std::max({value[0], value[1], value[2]});
                    for (int c = 0; c < 3; ++c) {
                        // 8-bit files are sRGB-decoded: encoding the texel again gives the code back,
                        // exactly (TIFF, lossless) or within 3 codes (JPEG at quality 100: flat
                        // blocks keep only their DC terms; the YCbCr round trip rounds).
                        EXPECT_NEAR(glsl::srgbEncode(tiff[c]) * 255.0f, float(code[c]), 0.01f) << x << "," << y;
                        EXPECT_NEAR(glsl::srgbEncode(jpeg[c]) * 255.0f, float(code[c]), 3.0f) << x << "," << y;
                        // Float files are linear: TIFF exactly; Radiance RGBE keeps 8 mantissa bits
                        // under the largest channel's exponent, so within 1/128 of that channel.
                        EXPECT_EQ(tiffFloat[c], value[c]) << x << "," << y;
                        EXPECT_NEAR(hdr[c], value[c], hdrMax / 128.0f) << x << "," << y;
                    }
                    EXPECT_EQ(jpeg.a, 1.0f);
                    EXPECT_EQ(hdr.a, 1.0f);
                }
    EXPECT_EQ(probes, 4 * 64);
    fs::remove_all(dir);
}

TEST(TextureFormats, ForgedSizesAreRefusedFromTheHeaderWithTheFileNamed) {
    // Headers that claim more pixels than raylab reads, with next to no pixel data behind them.
    const fs::path corpus = fs::path(RAYLAB_SOURCE_DIR) / "tests" / "data" / "malformed";
    for (const auto& [file, expected] :
         {std::pair<std::string, std::string>{"image_png_too_many_pixels.png",
                                              ": 16000x16800 is larger than raylab reads (at most 268435456 pixels)"},
          {"image_hdr_huge.hdr", ": 100000x100000 is larger than raylab reads (at most 32768 pixels per side)"},
          {"image_exr_wide.exr", ": 100000x1 is larger than raylab reads (at most 32768 pixels per side)"},
          {"image_exr_text.exr", ": "}}) {
        try {
            loadTexture(corpus / file);
            ADD_FAILURE() << file << ": no error";
        } catch (const TextureError& e) {
            EXPECT_EQ(std::string(e.what()).rfind((corpus / file).string() + expected, 0), 0u) << e.what();
        }
    }
}
