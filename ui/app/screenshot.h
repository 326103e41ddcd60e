#pragma once
// 8-bit RGBA pixels (the window's, as glReadPixels returns them: bottom row first) to a PNG file,
// written atomically like src/io/image_io.h does: a temporary sibling, then a rename.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace raylab::ui {

// Throws raylab::ImageIoError naming the path.
void writeRgba8Png(const std::filesystem::path& path, int width, int height,
                   const std::vector<std::uint8_t>& rgbaBottomUp);

} // namespace raylab::ui
