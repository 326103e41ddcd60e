#include "io/image_io.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("raylab_io_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}

Image ramp() {
    Image im(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            float* p = &im.rgba[size_t(y * 8 + x) * 4];
            p[0] = float(x) * 0.5f;   // goes above 1: HDR
            p[1] = float(y) * 0.25f;
            p[2] = 0.125f;
            p[3] = 1.0f;
        }
    return im;
}

} // namespace

TEST(ImageIo, ExrIsLinearFloatWithMetadataAndTopRowFirst) {
    const fs::path path = scratch("a.exr");
    RenderMetadata meta{64, 1.5, 42, "scenes/x.json", 3};
    writeImage(path, ramp(), meta, {});
    const Image back = readImage(path);
    EXPECT_EQ(back.rgba, ramp().rgba);
    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in);
    const auto& spec = in->spec();
    EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(spec.get_int_attribute("raylab:spp"), 64);
    EXPECT_EQ(spec.get_int_attribute("raylab:seed"), 42);
    EXPECT_FLOAT_EQ(spec.get_float_attribute("raylab:render_seconds"), 1.5f);
    EXPECT_EQ(spec.get_string_attribute("raylab:scene"), "scenes/x.json");
    EXPECT_EQ(spec.get_string_attribute("raylab:version"), RAYLAB_VERSION);
    EXPECT_EQ(spec.get_int_attribute("raylab:nonfinite_samples"), 3);
}

// An adaptive render's state rides in the EXR beside RGBA, exactly: readImage still gives the
// pixels, readAdaptiveState the counts (uint, past float's 2^24), the half image and the gate.
TEST(ImageIo, AnAdaptiveRendersStateIsInItsExrBesideThePixels) {
    const Image im = ramp();
    AdaptiveState state;
    for (std::uint32_t i = 0; i < 32; ++i) {
        state.samples.push_back(i == 5 ? (1u << 24) + 1u : i == 6 ? 4000000000u : 16u * i);
        for (int c = 0; c < 4; ++c) state.half.push_back(float(i) + 0.25f * float(c) + 1e-3f);
    }
    state.gateClosedAt = 77;
    const fs::path path = scratch("adaptive.exr");
    writeImage(path, im, RenderMetadata{}, DisplayTransform{}, &state);
    EXPECT_EQ(readImage(path).rgba, im.rgba) << "R, G, B, A stay the first four channels";
    const std::optional<AdaptiveState> back = readAdaptiveState(path);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->samples, state.samples);
    EXPECT_EQ(back->half, state.half);
    EXPECT_EQ(back->gateClosedAt, 77u);

    const fs::path plain = scratch("plain.exr");
    writeImage(plain, im, RenderMetadata{}, DisplayTransform{});
    EXPECT_FALSE(readAdaptiveState(plain));
    const fs::path png = scratch("adaptive.png");
    writeImage(png, im, RenderMetadata{}, DisplayTransform{}, &state);
    EXPECT_FALSE(readAdaptiveState(png)) << "a PNG leaves the state out";

    // Some of the channels only: named.
    const fs::path partial = scratch("partial.exr");
    {
        auto out = OIIO::ImageOutput::create(partial.string());
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(8, 4, 5, OIIO::TypeDesc::FLOAT);
        spec.channelnames = {"R", "G", "B", "A", "adaptive.samples"};
        std::vector<float> pixels(8 * 4 * 5, 1.0f);
        ASSERT_TRUE(out->open(partial.string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
        ASSERT_TRUE(out->close());
    }
    try {
        readAdaptiveState(partial);
        ADD_FAILURE() << "no error";
    } catch (const ImageIoError& e) {
        EXPECT_NE(std::string(e.what()).find(partial.string() + ": error: an adaptive render's EXR without its channel "
                                                                "adaptive.half.R"),
                  std::string::npos) << e.what();
    }
}

TEST(ImageIo, PngIsExposedToneMappedAndSrgbEncoded) {
    const fs::path path = scratch("b.png");
    Image im(2, 1);
    im.rgba = {0.5f, 0.5f, 0.5f, 1.0f, 4.0f, 0.0f, 0.0f, 1.0f};
    writeImage(path, im, {}, {0.0f, ToneMap::Clamp});
    Image back = readImage(path);   // 8-bit values read as [0, 1]
    EXPECT_NEAR(back.rgba[0], 188.0f / 255.0f, 1e-6f);   // sRGB(0.5) = 0.7354 → 188
    EXPECT_NEAR(back.rgba[4], 1.0f, 1e-6f);              // clamped
    writeImage(path, im, {}, {1.0f, ToneMap::Reinhard});   // 0.5·2 = 1 → 0.5 → 188
    back = readImage(path);
    EXPECT_NEAR(back.rgba[0], 188.0f / 255.0f, 1e-6f);
    EXPECT_EQ(displayByte(0.0f, {0.0f, ToneMap::AcesFit}), 0);
}

TEST(ImageIo, WritesAreAtomicAndLeaveNoTemporaryFiles) {
    const fs::path path = scratch("c.exr");
    writeImage(path, ramp(), {}, {});
    writeImage(path, ramp(), {}, {});   // replaces
    int files = 0;
    for (const auto& e : fs::directory_iterator(path.parent_path()))
        files += e.path().filename().string().find(".tmp") != std::string::npos;
    EXPECT_EQ(files, 0);
}

TEST(ImageIo, BadPathsAndFormatsFailWithTheFileNamed) {
    try {
        checkWritable("/nonexistent_dir_raylab/out.png");
        FAIL();
    } catch (const ImageIoError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent_dir_raylab/out.png: error: cannot write"),
                  std::string::npos) << e.what();
    }
    try {
        checkWritable(scratch("out.bmpx"));
        FAIL();
    } catch (const ImageIoError& e) {
        EXPECT_NE(std::string(e.what()).find("unsupported output format '.bmpx'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(readImage("/nonexistent_dir_raylab/in.exr"), ImageIoError);
}

TEST(ImageIo, ReadsRefuseForgedSizesBeforeAllocatingAndNameTheFile) {
    const fs::path wide = scratch("wide.hdr");
    std::ofstream(wide, std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 40000\n" << std::string(16, '\0');
    try {
        readImage(wide);
        FAIL() << "no error";
    } catch (const ImageIoError& e) {
        EXPECT_EQ(std::string(e.what()), wide.string() + ": error: cannot read: 40000x2 is larger than raylab reads "
                                                          "(at most 32768 pixels per side)");
    }
    const fs::path garbage = scratch("garbage.exr");
    std::ofstream(garbage, std::ios::binary) << "not an image";
    try {
        readImage(garbage);
        FAIL() << "no error";
    } catch (const ImageIoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(garbage.string() + ": error: cannot read: ", 0), 0u) << e.what();
    }
}
