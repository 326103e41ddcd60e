#include "texture/image_size.h"

#include "io/stderr_capture.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstring>

namespace raylab {

std::optional<std::string> imageSizeProblem(std::int64_t width, std::int64_t height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) return size + " is not an image size";
    if (width > kMaxImageSide || height > kMaxImageSide)
        return size + " is larger than raylab reads (at most " + std::to_string(kMaxImageSide) + " pixels per side)";
    if (width * height > kMaxImageTexels)
        return size + " is larger than raylab reads (at most " + std::to_string(kMaxImageTexels) + " pixels)";
    return std::nullopt;
}

std::optional<ImageSize> encodedImageSize(const unsigned char* bytes, std::size_t size) {
    const char* format = nullptr;
    if (size >= 8 && std::memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0) format = "png";
    else if (size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff) format = "jpg";
    if (!format) return std::nullopt;
    // libpng's lines are dropped: the full decoder that runs next reports the problem itself.
    StderrCapture decoder;
    OIIO::Filesystem::IOMemReader memory(bytes, size);
    auto in = OIIO::ImageInput::create(format, false, nullptr, &memory);
    if (!in) return std::nullopt;
    in->set_ioproxy(&memory);
    OIIO::ImageSpec spec;
    if (!in->open(std::string("memory.") + format, spec)) {
        (void)in->geterror();   // consumed here; the decoder reports the problem
        return std::nullopt;
    }
    in->close();
    return ImageSize{spec.width, spec.height};
}

} // namespace raylab
