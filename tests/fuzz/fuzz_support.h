#pragma once
// What the libFuzzer harnesses share: a temporary folder per process holding tiny files a fuzzed
// input may name (tiny.obj, tiny.gltf, tiny.ppm, tiny.hdr, scene.json), writing an input there,
// and the one filter every harness applies before loading.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <unistd.h>

namespace raylab::fuzz {

inline void writeFile(const std::filesystem::path& file, std::string_view bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Removed at exit, so a long run leaves nothing behind in /tmp.
struct ScratchDir {
    std::filesystem::path path;
    ScratchDir() {
        path = std::filesystem::temp_directory_path() / ("raylab_fuzz_" + std::to_string(::getpid()));
        std::filesystem::create_directories(path);
        writeFile(path / "tiny.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n");
        writeFile(path / "tiny.gltf",
                  R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
                  R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
                  R"("buffers":[{"byteLength":36,"uri":"tiny.bin"}],)"
                  R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
                  R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
                  R"("min":[0,0,0],"max":[1,1,0]}]})");
        static const float kTriangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        writeFile(path / "tiny.bin", std::string_view(reinterpret_cast<const char*>(kTriangle), sizeof kTriangle));
        writeFile(path / "tiny.ppm", std::string_view("P6\n2 2\n255\n\x10\x20\x30\x40\x50\x60\x70\x80\x90\xa0\xb0\xc0", 23));
        writeFile(path / "tiny.hdr", std::string_view("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n"
                                                      "\x80\x80\x80\x81\x40\x40\x40\x81", 53));
        writeFile(path / "scene.json", R"({"objects": [{"type": "sphere"}]})");
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

inline const std::filesystem::path& scratchDir() {
    static const ScratchDir dir;
    return dir.path;
}

// Inputs naming device or kernel files are skipped: reading /dev/zero or /dev/stdin never ends,
// which is the file's doing, not the parser's.
inline bool namesASpecialFile(std::string_view input) {
    for (std::string_view special : {"/dev", "/proc", "/sys"})
        if (input.find(special) != std::string_view::npos) return true;
    return false;
}

// An exception the harness does not expect is a finding: print it and abort, so libFuzzer keeps
// the input (libFuzzer reports an escaping exception only as a plain crash without its text).
[[noreturn]] inline void unexpected(const char* harness, const char* what) {
    std::fprintf(stderr, "%s: unexpected exception: %s\n", harness, what);
    std::abort();
}

} // namespace raylab::fuzz
