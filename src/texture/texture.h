#pragma once
// Image textures: read through OpenImageIO (PNG, JPEG, EXR, HDR, TIFF, ...), converted to linear
// RGBA float (8- and 16-bit files are taken as sRGB-encoded and decoded; float files as linear),
// with a box-filtered mip pyramid down to 1×1. Layout on the GPU: shaders/include/texture.glsl.
#include <glm/glm.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab {

class TextureError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct MipLevel {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels;   // row-major, row 0 = v 0 (the image's bottom row)
};

// How uv outside [0, 1) is mapped (glTF sampler wrapS / wrapT); scene-file textures repeat.
enum class TextureWrap : unsigned { Repeat = 0, ClampToEdge = 1, MirroredRepeat = 2 };

struct Texture {
    std::string file;               // "srgb:" or "linear:" + the path as written in the scene
    std::vector<MipLevel> levels;   // levels[0] is the image
    TextureWrap wrapU = TextureWrap::Repeat;
    TextureWrap wrapV = TextureWrap::Repeat;
};

// Reads the file; the message of a TextureError starts with the path. `linearData`: 8/16-bit
// values are taken as they are (normal maps), not decoded from sRGB.
Texture loadTexture(const std::filesystem::path& path, bool linearData = false);
// From decoded 8- or 16-bit pixels (`bits`), `channels` per texel, rows top first as in image files;
// sRGB-decoded unless linearData. Used for glTF images (decoded by tinygltf).
Texture textureFromPixels(const unsigned char* pixels, int width, int height, int channels, int bits, bool linearData);
// Builds the pyramid from one level (used by loadTexture; public for tests and generated textures).
std::vector<MipLevel> buildMipPyramid(MipLevel base);

} // namespace raylab
