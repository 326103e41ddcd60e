#include "app/screenshot.h"

#include "io/image_io.h"

#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <string>

namespace raylab::ui {

void writeRgba8Png(const std::filesystem::path& path, int width, int height,
                   const std::vector<std::uint8_t>& rgbaBottomUp) {
    using namespace OIIO;
    std::filesystem::path tmp = path;
    tmp.replace_filename("." + path.stem().string() + ".tmp" + std::to_string(::getpid()) + ".png");
    auto out = ImageOutput::create("png");
    if (!out) throw ImageIoError(path.string() + ": error: " + OIIO::geterror());
    ImageSpec spec(width, height, 3, TypeDesc::UINT8);
    spec.attribute("Software", "raylab " RAYLAB_VERSION);
    std::vector<std::uint8_t> rgb(std::size_t(width) * height * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                rgb[(std::size_t(y) * width + x) * 3 + c] =
                    rgbaBottomUp[(std::size_t(height - 1 - y) * width + x) * 4 + c];
    bool ok = out->open(tmp.string(), spec) && out->write_image(TypeDesc::UINT8, rgb.data());
    ok = out->close() && ok;
    std::error_code ec;
    if (ok) std::filesystem::rename(tmp, path, ec);
    if (!ok || ec) {
        const std::string why = ok ? ec.message() : out->geterror();
        std::filesystem::remove(tmp, ec);
        throw ImageIoError(path.string() + ": error: cannot write: " + why);
    }
}

} // namespace raylab::ui
