#pragma once
// Writes small glTF 2.0 test assets (no downloads): a unit quad or two in the z = 0 plane with
// positions, normals, uvs and indices in one embedded buffer, materials given as JSON text, and
// PNG images as external files, data URIs or GLB buffer views.
#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

namespace raylab::test {

inline std::string base64(const std::vector<unsigned char>& data) {
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

// An 8-bit PNG file of w × h texels, `channels` values each, top row first.
inline void writePng(const std::filesystem::path& path, int w, int h, int channels, const std::vector<unsigned char>& px) {
    auto out = OIIO::ImageOutput::create(path.string());
    OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);   // write the values as given (no un-premultiplying)
    if (!out || !out->open(path.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::UINT8, px.data()))
        throw std::runtime_error("cannot write " + path.string());
    out->close();
}

inline std::vector<unsigned char> readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<unsigned char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The bytes of a PNG (written through a scratch file, since OIIO writes files).
inline std::vector<unsigned char> pngBytes(int w, int h, int channels, const std::vector<unsigned char>& px) {
    const std::filesystem::path tmp =
        std::filesystem::temp_directory_path() / ("raylab_png_" + std::to_string(::getpid()) + ".png");
    writePng(tmp, w, h, channels, px);
    std::vector<unsigned char> bytes = readBytes(tmp);
    std::filesystem::remove(tmp);
    return bytes;
}

template <class T>
void appendValues(std::vector<unsigned char>& bytes, std::initializer_list<T> values) {
    for (T v : values) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &v, sizeof(T));
        for (unsigned char c : b) bytes.push_back(c);
    }
}

// The geometry: `quads` unit squares side by side along x (quad q spans x in [q - 1, q],
// y in [-0.5, 0.5] after the root node's translation by `translateX`), uvs (0,0)…(1,1) with glTF's
// v = 0 at the top, one primitive per quad whose material is materials[q] (-1 = none).
struct GltfSpec {
    std::vector<int> primitiveMaterials = {0};
    std::string materials = "[]";   // JSON array text
    std::string textures = "[]";
    std::string images = "[]";
    std::string samplers = "[]";
    std::string extensionsUsed;    // JSON array text or empty
    float translateX = 0.0f;
    std::vector<unsigned char> glbImage;   // GLB only: PNG bytes placed in bufferView 3 (image "bufferView": 3)
};

inline std::string gltfJson(const GltfSpec& s, const std::vector<unsigned char>& buffer, bool glb) {
    const std::size_t quads = s.primitiveMaterials.size();
    std::ostringstream j;
    j << R"({ "asset": { "version": "2.0" }, "scene": 0, "scenes": [ { "nodes": [0] } ],)";
    if (!s.extensionsUsed.empty()) j << R"( "extensionsUsed": )" << s.extensionsUsed << ",";
    j << R"( "nodes": [ { "translation": [)" << s.translateX << R"(, 0, 0], "children": [1] }, { "mesh": 0 } ],)";
    j << R"( "meshes": [ { "primitives": [)";
    for (std::size_t q = 0; q < quads; ++q) {
        j << (q ? ", " : "") << R"({ "attributes": { "POSITION": )" << 3 * q << R"(, "NORMAL": )" << 3 * q + 1
          << R"(, "TEXCOORD_0": )" << 3 * q + 2 << R"( }, "indices": )" << 3 * quads;
        if (s.primitiveMaterials[q] >= 0) j << R"(, "material": )" << s.primitiveMaterials[q];
        j << " }";
    }
    j << "] } ], \"accessors\": [";
    for (std::size_t q = 0; q < quads; ++q) {
        const std::size_t base = q * 128;
        j << (q ? ", " : "") << R"({ "bufferView": 0, "byteOffset": )" << base
          << R"(, "componentType": 5126, "count": 4, "type": "VEC3", "min": [)" << float(q) - 1.0f
          << R"(, -0.5, 0], "max": [)" << float(q) << R"(, 0.5, 0] },)"
          << R"({ "bufferView": 0, "byteOffset": )" << base + 48 << R"(, "componentType": 5126, "count": 4, "type": "VEC3" },)"
          << R"({ "bufferView": 1, "byteOffset": )" << q * 32 << R"(, "componentType": 5126, "count": 4, "type": "VEC2" })";
    }
    j << R"(, { "bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR" } ],)";
    const std::size_t uvStart = quads * 128, indexStart = uvStart + quads * 32;
    j << R"( "bufferViews": [ { "buffer": 0, "byteOffset": 0, "byteLength": )" << uvStart << " },"
      << R"( { "buffer": 0, "byteOffset": )" << uvStart << R"(, "byteLength": )" << quads * 32 << " },"
      << R"( { "buffer": 0, "byteOffset": )" << indexStart << R"(, "byteLength": 12 })";
    if (glb && !s.glbImage.empty())
        j << R"(, { "buffer": 0, "byteOffset": )" << indexStart + 12 << R"(, "byteLength": )" << s.glbImage.size() << " }";
    j << "],";
    if (glb) j << R"( "buffers": [ { "byteLength": )" << buffer.size() << " } ],";
    else j << R"( "buffers": [ { "byteLength": )" << buffer.size() << R"(, "uri": "data:application/octet-stream;base64,)"
           << base64(buffer) << R"(" } ],)";
    j << R"( "materials": )" << s.materials << R"(, "textures": )" << s.textures << R"(, "images": )" << s.images
      << R"(, "samplers": )" << s.samplers << " }";
    return j.str();
}

inline std::vector<unsigned char> gltfBuffer(const GltfSpec& s, bool glb) {
    std::vector<unsigned char> b;
    const std::size_t quads = s.primitiveMaterials.size();
    for (std::size_t q = 0; q < quads; ++q) {
        const float x0 = float(q) - 1.0f, x1 = float(q);
        appendValues<float>(b, {x0, -0.5f, 0, x1, -0.5f, 0, x1, 0.5f, 0, x0, 0.5f, 0});   // 48 bytes
        appendValues<float>(b, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});                     // 48 bytes
        b.resize(b.size() + 32, 0);                                                       // pad to 128
    }
    for (std::size_t q = 0; q < quads; ++q) appendValues<float>(b, {0, 1, 1, 1, 1, 0, 0, 0});   // glTF v down
    appendValues<std::uint16_t>(b, {0, 1, 2, 0, 2, 3});
    if (glb) b.insert(b.end(), s.glbImage.begin(), s.glbImage.end());
    while (b.size() % 4) b.push_back(0);
    return b;
}

inline void writeGltf(const std::filesystem::path& path, const GltfSpec& s) {
    std::ofstream(path) << gltfJson(s, gltfBuffer(s, false), false);
}

// GLB container (glTF 2.0 §4.4): header, JSON chunk (space padded), BIN chunk.
inline void writeGlb(const std::filesystem::path& path, const GltfSpec& s) {
    const std::vector<unsigned char> bin = gltfBuffer(s, true);
    std::string json = gltfJson(s, bin, true);
    while (json.size() % 4) json += ' ';
    std::vector<unsigned char> out;
    const std::uint32_t total = std::uint32_t(12 + 8 + json.size() + 8 + bin.size());
    appendValues<std::uint32_t>(out, {0x46546C67u, 2u, total, std::uint32_t(json.size()), 0x4E4F534Au});
    out.insert(out.end(), json.begin(), json.end());
    appendValues<std::uint32_t>(out, {std::uint32_t(bin.size()), 0x004E4942u});
    out.insert(out.end(), bin.begin(), bin.end());
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
}

} // namespace raylab::test
