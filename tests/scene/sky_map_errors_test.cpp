// A sky map that is not a readable image, or one too large to read, is refused when the scene is
// read, at sky.map, before any pixel is allocated.
#include "scene/scene_loader.h"
#include "support/render_cli.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

// This process's own folder: ctest runs the tests of this file in parallel processes.
fs::path scratch() { return test::scratchDir("raylab_sky_map_errors"); }

// The error of a scene in `dir` whose sky map is `map`, or "<no error>".
std::string errorWithMap(const std::string& map) {
    const fs::path scene = scratch() / "sky.json";
    std::ofstream(scene) << "{ \"sky\": { \"type\": \"map\",\n  \"map\": \"" << map << "\" },\n"
                         << "  \"objects\": [ {} ] }\n";
    try {
        loadScene(scene);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "<no error>";
}

std::string prefix(const std::string& map) {
    return (scratch() / "sky.json").string() + ":2:10: error: sky.map: " + (scratch() / map).string() + ": ";
}

void write(const std::string& name, const std::string& bytes) {
    std::ofstream(scratch() / name, std::ios::binary) << bytes;
}

// A Radiance .hdr header for width x height, followed by `pixels`.
std::string hdr(long width, long height, const std::string& pixels) {
    return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " + std::to_string(width) +
           "\n" + pixels;
}

} // namespace

TEST(SkyMapErrors, AReadableMapLoads) {
    fs::copy_file(fs::path(RAYLAB_SOURCE_DIR) / "scenes" / "sky_procedural.hdr", scratch() / "good.hdr",
                  fs::copy_options::overwrite_existing);
    EXPECT_EQ(errorWithMap("good.hdr"), "<no error>");
    write("tiny.hdr", hdr(2, 1, std::string("\x80\x80\x80\x81\x40\x40\x40\x81", 8)));
    EXPECT_EQ(errorWithMap("tiny.hdr"), "<no error>");
}

TEST(SkyMapErrors, GarbageIsALocatedErrorAtSkyMap) {
    write("garbage.hdr", "this is not an image\n");
    const std::string garbage = errorWithMap("garbage.hdr");
    EXPECT_EQ(garbage.rfind(prefix("garbage.hdr") + "cannot read: ", 0), 0u) << garbage;
    write("garbage.exr", std::string("\x76\x2f\x31\x01", 4) + "garbage after the magic number");
    const std::string exr = errorWithMap("garbage.exr");
    EXPECT_EQ(exr.rfind(prefix("garbage.exr") + "cannot read: ", 0), 0u) << exr;
    write("empty.hdr", "");
    const std::string empty = errorWithMap("empty.hdr");
    EXPECT_EQ(empty.rfind(prefix("empty.hdr") + "cannot read: ", 0), 0u) << empty;
}

TEST(SkyMapErrors, PixelsThatDoNotDecodeAreFound) {
    write("truncated.hdr", hdr(64, 64, std::string(100, '\x40')));   // 64x64 pixels need 16 KiB
    const std::string truncated = errorWithMap("truncated.hdr");
    EXPECT_EQ(truncated.rfind(prefix("truncated.hdr") + "cannot read: ", 0), 0u) << truncated;
}

TEST(SkyMapErrors, AHugeHeaderIsRefusedBeforeAnyAllocation) {
    write("huge.hdr", hdr(200000, 100000, "tiny"));   // 240 GB as RGBA floats
    EXPECT_EQ(errorWithMap("huge.hdr"),
              prefix("huge.hdr") + "200000x100000 is larger than raylab reads (at most 32768 pixels per side)");
    write("many.hdr", hdr(32768, 16384, "tiny"));
    EXPECT_EQ(errorWithMap("many.hdr"),
              prefix("many.hdr") + "32768x16384 is larger than raylab reads (at most 268435456 pixels)");
}
