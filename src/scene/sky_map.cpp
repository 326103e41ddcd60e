#include "scene/sky_map.h"

#include "io/stderr_capture.h"
#include "texture/image_size.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace raylab::scenefmt {
namespace {

constexpr int kStripRows = 64;   // rows decoded at once while checking

std::string oiioError(const std::string& error, const char* otherwise) {
    return error.empty() ? otherwise : error;
}

} // namespace

std::optional<std::string> skyMapProblem(const std::filesystem::path& file) {
    using namespace OIIO;
    StderrCapture decoder;   // the decoders' own lines belong in the message
    auto in = ImageInput::open(file.string());
    if (!in)
        return "cannot read: " +
               withDecoderText(oiioError(OIIO::geterror(), "not an image file OpenImageIO knows"), decoder.finish());
    const ImageSpec spec = in->spec();
    const std::int64_t w = spec.width, h = spec.height;
    if (w <= 0 || h <= 0) return "cannot read: " + std::to_string(w) + "x" + std::to_string(h) + " is not an image size";
    if (std::optional<std::string> tooLarge = imageSizeProblem(w, h)) return *tooLarge;
    if (spec.nchannels <= 0 || spec.depth > 1 || spec.deep) return "cannot read: not a flat image with channels";
    const int channels = std::min(spec.nchannels, 4);
    const int strip = spec.tile_height > 0 ? std::min(spec.tile_height, spec.height) : kStripRows;
    std::vector<float> pixels(std::size_t(w) * std::size_t(strip) * std::size_t(channels));
    for (int y = spec.y; y < spec.y + spec.height; y += strip) {
        const int end = std::min(y + strip, spec.y + spec.height);
        const bool ok = spec.tile_width > 0
                            ? in->read_tiles(0, 0, spec.x, spec.x + spec.width, y, end, spec.z, spec.z + 1, 0, channels,
                                             TypeDesc::FLOAT, pixels.data())
                            : in->read_scanlines(0, 0, y, end, spec.z, 0, channels, TypeDesc::FLOAT, pixels.data());
        if (!ok) return "cannot read: " + withDecoderText(oiioError(in->geterror(), "the pixels do not decode"), decoder.finish());
    }
    in->close();
    return std::nullopt;
}

} // namespace raylab::scenefmt
