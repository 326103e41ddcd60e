// glTF 2.0 meshes: a small file written here (embedded base64 buffer, a two-level node
// hierarchy), loaded through the scene's "file" key.
#include "scene/gltf_loader.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

std::string base64(const std::vector<unsigned char>& data) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < data.size(); i += 3) {
        const unsigned v = unsigned(data[i]) << 16 | (i + 1 < data.size() ? unsigned(data[i + 1]) << 8 : 0u) |
                           (i + 2 < data.size() ? unsigned(data[i + 2]) : 0u);
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < data.size() ? table[(v >> 6) & 63] : '=';
        out += i + 2 < data.size() ? table[v & 63] : '=';
    }
    return out;
}

template <class T>
void append(std::vector<unsigned char>& bytes, std::initializer_list<T> values) {
    for (T v : values) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &v, sizeof(T));
        bytes.insert(bytes.end(), b, b + sizeof(T));
    }
}

// One triangle (positions, normals, uvs, 16-bit indices) under node "child" (scale 2) under
// node "root" (translation [0, 0, 5], rotation 90° about z).
std::string triangleGltf() {
    std::vector<unsigned char> b;
    append<float>(b, {0, 0, 0, 1, 0, 0, 0, 1, 0});   // 0: positions, 36 bytes
    append<float>(b, {0, 0, 1, 0, 0, 1, 0, 0, 1});   // 36: normals
    append<float>(b, {0, 0, 1, 0, 0, 1});            // 72: uvs, 24 bytes
    append<std::uint16_t>(b, {0, 1, 2, 0});          // 96: indices (+ 2 bytes padding)
    const float s = std::sqrt(0.5f);
    return R"({ "asset": { "version": "2.0" }, "scene": 0, "scenes": [ { "nodes": [0] } ],
      "nodes": [ { "name": "root", "translation": [0, 0, 5], "rotation": [0, 0, )" + std::to_string(s) + ", " +
           std::to_string(s) + R"(], "children": [1] },
                 { "name": "child", "scale": [2, 2, 2], "mesh": 0 } ],
      "meshes": [ { "primitives": [ { "attributes": { "POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2 }, "indices": 3 } ] } ],
      "accessors": [
        { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0] },
        { "bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3" },
        { "bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2" },
        { "bufferView": 3, "componentType": 5123, "count": 3, "type": "SCALAR" } ],
      "bufferViews": [ { "buffer": 0, "byteOffset": 0, "byteLength": 36 },
                       { "buffer": 0, "byteOffset": 36, "byteLength": 36 },
                       { "buffer": 0, "byteOffset": 72, "byteLength": 24 },
                       { "buffer": 0, "byteOffset": 96, "byteLength": 6 } ],
      "buffers": [ { "byteLength": 104, "uri": "data:application/octet-stream;base64,)" + base64(b) + R"(" } ] })";
}

} // namespace

TEST(GltfLoader, NodeTransformsAttributesAndIndices) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_gltf_test_" + std::to_string(::getpid()));
    fs::create_directories(dir / "models");
    std::ofstream(dir / "models" / "tri.gltf") << triangleGltf();
    std::ofstream(dir / "scene.json") << R"({ "objects": [ { "type": "mesh", "file": "models/tri.gltf" } ] })";
    const Scene scene = loadScene(dir / "scene.json");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& m = scene.meshes[0];
    ASSERT_EQ(m.positions.size(), 3u);
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
    // (1, 0, 0) scaled by 2, turned 90° about z, moved to z = 5: (0, 2, 5).
    EXPECT_NEAR(m.positions[1].x, 0.0f, 1e-5f);
    EXPECT_NEAR(m.positions[1].y, 2.0f, 1e-5f);
    EXPECT_NEAR(m.positions[1].z, 5.0f, 1e-5f);
    EXPECT_NEAR(m.positions[2].x, -2.0f, 1e-5f);
    ASSERT_EQ(m.normals.size(), 3u);
    EXPECT_NEAR(m.normals[0].z, 1.0f, 1e-5f);
    ASSERT_EQ(m.uvs.size(), 3u);
    EXPECT_EQ(m.uvs[1], glm::vec2(1.0f, 1.0f)) << "glTF's v = 0 is the top of the image";
    // A broken file names the scene, the key and the glTF file.
    std::ofstream(dir / "models" / "bad.gltf") << "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ ";
    std::ofstream(dir / "bad.json") << R"({ "objects": [ { "type": "mesh", "file": "models/bad.gltf" } ] })";
    try {
        loadScene(dir / "bad.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("bad.json:1:42: error: objects[0].file: " + (dir / "models" / "bad.gltf").string() + ": "),
                  std::string::npos)
            << msg;
    }
    fs::remove_all(dir);
}

namespace {

// What loadGltf says about the triangle file with `from` replaced by `to`, after the file's name.
std::string gltfErrorOf(const std::string& from, const std::string& to) {
    std::string text = triangleGltf();
    const std::size_t at = text.find(from);
    if (at == std::string::npos) return "<'" + from + "' not in the file>";
    text.replace(at, from.size(), to);
    const fs::path dir = fs::temp_directory_path() / ("raylab_gltf_bad_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "bad.gltf";
    std::ofstream(file) << text;
    try {
        loadGltf(file);
    } catch (const GltfError& e) {
        const std::string msg = e.what();
        return msg.rfind(file.string() + ": ", 0) == 0 ? msg.substr(file.string().size() + 2) : "(file not named) " + msg;
    }
    return "<no error>";
}

} // namespace

// A uri naming a folder: tinygltf's own reader took its size as 2^63 - 1 and allocated that (a
// fuzzer's find); raylab reads the files a glTF names itself.
TEST(GltfLoader, AUriNamingAFolderIsRefused) {
    const std::string message = gltfErrorOf(R"("uri": "data:application/octet-stream;base64,)", R"("uri": "../", "x": ")");
    EXPECT_NE(message.find("cannot read: not a file"), std::string::npos) << message;
}

TEST(GltfLoader, AccessorsAndIndicesAreCheckedWithoutOverflow) {
    const std::string view0 = R"({ "buffer": 0, "byteOffset": 0, "byteLength": 36 })";
    EXPECT_EQ(gltfErrorOf(R"("count": 3, "type": "VEC2")", R"("count": 3, "type": "VEC2", "byteOffset": 18446744073709551608)"),
              "accessors[2]: byteOffset 18446744073709551608 + count 3 x stride 8 is past the end of bufferViews[2] "
              "(byteLength 24)");
    EXPECT_EQ(gltfErrorOf(R"("count": 3, "type": "VEC3", "min")", R"("count": 4611686018427387905, "type": "VEC3", "min")"),
              "accessors[0]: byteOffset 0 + count 4611686018427387905 x stride 12 is past the end of bufferViews[0] "
              "(byteLength 36)");
    EXPECT_EQ(gltfErrorOf(view0, R"({ "buffer": 3, "byteOffset": 0, "byteLength": 36 })"),
              "bufferViews[0].buffer: 3 is not a buffer (1 in the file)");
    EXPECT_EQ(gltfErrorOf(view0, R"({ "buffer": 0, "byteOffset": 100, "byteLength": 36 })"),
              "bufferViews[0]: byteOffset 100 + byteLength 36 is past the end of buffers[0] (104 bytes)");
    EXPECT_EQ(gltfErrorOf(R"("TEXCOORD_0": 2)", R"("TEXCOORD_0": 7)"),
              "meshes[0].primitives[0].attributes.TEXCOORD_0: 7 is not an accessor (4 in the file)");
    EXPECT_EQ(gltfErrorOf(R"("componentType": 5123, "count": 3, "type": "SCALAR")",
                          R"("componentType": 5123, "count": 3, "type": "VEC2")"),
              "accessors[3].type: meshes[0].primitives[0].indices needs 1 component per element, got 2");
    EXPECT_EQ(gltfErrorOf(R"("scale": [2, 2, 2])", R"("scale": [2, 1e39, 2])"), "nodes[1].scale[1]: not a finite 32-bit float");
    EXPECT_EQ(gltfErrorOf(R"("children": [1])", R"("children": [0])"), "nodes[0]: the node is reached twice (glTF nodes form a tree)");
}
