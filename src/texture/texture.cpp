#include "texture/texture.h"

#include "io/stderr_capture.h"
#include "texture/image_size.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <string>

namespace raylab {
namespace {

float srgbDecode(float v) {   // IEC 61966-2-1
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

} // namespace

std::vector<MipLevel> buildMipPyramid(MipLevel base) {
    std::vector<MipLevel> levels;
    levels.push_back(std::move(base));
    while (levels.back().width > 1 || levels.back().height > 1) {
        const MipLevel& src = levels.back();
        MipLevel dst;
        dst.width = std::max(1, src.width / 2);
        dst.height = std::max(1, src.height / 2);
        dst.texels.resize(std::size_t(dst.width) * std::size_t(dst.height));
        // Box filter over the 2×2 (or, for an odd last row/column, up to 3×3) source texels.
        for (int y = 0; y < dst.height; ++y)
            for (int x = 0; x < dst.width; ++x) {
                const int x0 = 2 * x, y0 = 2 * y;
                const int x1 = (x == dst.width - 1) ? src.width : std::min(src.width, x0 + 2);
                const int y1 = (y == dst.height - 1) ? src.height : std::min(src.height, y0 + 2);
                glm::vec4 sum(0.0f);
                for (int sy = y0; sy < y1; ++sy)
                    for (int sx = x0; sx < x1; ++sx) sum += src.texels[std::size_t(sy) * std::size_t(src.width) + std::size_t(sx)];
                dst.texels[std::size_t(y) * std::size_t(dst.width) + std::size_t(x)] = sum / float((x1 - x0) * (y1 - y0));
            }
        levels.push_back(std::move(dst));
    }
    return levels;
}

Texture loadTexture(const std::filesystem::path& path, bool linearData) {
    using namespace OIIO;
    const std::string name = path.string();
    StderrCapture decoder;   // libpng prints its errors; they belong in the message
    auto in = ImageInput::open(name);
    if (!in) {
        std::string err = geterror();
        if (err.empty()) err = "cannot open";
        throw TextureError(name + ": " + withDecoderText(err, decoder.finish()));
    }
    const ImageSpec& spec = in->spec();
    const int w = spec.width, h = spec.height, c = spec.nchannels;
    if (const auto problem = imageSizeProblem(w, h)) throw TextureError(name + ": " + *problem);
    if (c <= 0) throw TextureError(name + ": the image has no channels");
    if (spec.depth > 1 || spec.deep) throw TextureError(name + ": volume and deep images are not supported");
    const int read = std::min(c, 4);   // rgba: further channels are never used
    MipLevel base;
    base.width = w;
    base.height = h;
    std::vector<float> raw;
    try {
        raw.resize(std::size_t(w) * std::size_t(h) * std::size_t(read));
        base.texels.resize(std::size_t(w) * std::size_t(h));
    } catch (const std::bad_alloc&) {
        throw TextureError(name + ": not enough memory for a " + std::to_string(w) + "x" + std::to_string(h) + " image");
    }
    if (!in->read_image(0, 0, 0, read, TypeDesc::FLOAT, raw.data())) {
        std::string err = in->geterror();
        if (err.empty()) err = "cannot read the pixels";
        throw TextureError(name + ": " + withDecoderText(err, decoder.finish()));
    }
    in->close();
    (void)decoder.finish();   // a decoder's remarks on an image it read are not the user's concern
    const bool encoded = !linearData && !spec.format.is_floating_point();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* p = &raw[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * std::size_t(read)];
            glm::vec4 v(p[0], read > 1 ? p[1] : p[0], read > 2 ? p[2] : p[0], read > 3 ? p[3] : 1.0f);
            if (encoded)
                for (int k = 0; k < 3; ++k) v[k] = srgbDecode(v[k]);
            // Files store the top row first; v = 0 is the bottom (OpenGL convention).
            base.texels[std::size_t(h - 1 - y) * std::size_t(w) + std::size_t(x)] = v;
        }
    Texture t;
    t.levels = buildMipPyramid(std::move(base));
    return t;
}

Texture textureFromPixels(const unsigned char* pixels, int width, int height, int channels, int bits, bool linearData) {
    if (width <= 0 || height <= 0 || channels <= 0 || (bits != 8 && bits != 16))
        throw TextureError("unsupported image layout (" + std::to_string(width) + "x" + std::to_string(height) + ", " +
                           std::to_string(channels) + " channels, " + std::to_string(bits) + " bits)");
    if (const auto problem = imageSizeProblem(width, height)) throw TextureError(*problem);
    const std::size_t bytes = std::size_t(bits / 8);
    auto value = [&](std::size_t i) {
        if (bytes == 1) return float(pixels[i]) / 255.0f;
        std::uint16_t s = 0;
        std::memcpy(&s, pixels + 2 * i, 2);   // tinygltf hands 16-bit pixels in host order
        return float(s) / 65535.0f;
    };
    MipLevel base;
    base.width = width;
    base.height = height;
    base.texels.resize(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels);
            const float r = value(i);
            // Grey (+alpha) images spread their one value over rgb, as loadTexture does.
            glm::vec4 v(r, channels > 2 ? value(i + 1) : r, channels > 2 ? value(i + 2) : r,
                        channels == 4 ? value(i + 3) : (channels == 2 ? value(i + 1) : 1.0f));
            if (!linearData)
                for (int k = 0; k < 3; ++k) v[k] = srgbDecode(v[k]);
            base.texels[std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)] = v;
        }
    Texture t;
    t.levels = buildMipPyramid(std::move(base));
    return t;
}

} // namespace raylab
