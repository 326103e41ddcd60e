#pragma once
// The largest image raylab reads (textures, glTF images, sky maps), checked from the file's header
// before any pixel is allocated, so a forged header cannot ask for gigabytes.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace raylab {

inline constexpr std::int64_t kMaxImageSide = 32768;                    // pixels per side (2:1 panoramas)
inline constexpr std::int64_t kMaxImageTexels = std::int64_t(1) << 28;   // width × height

// The complaint about an image of that size ("65535x65535 is larger than ..."), or nullopt when
// raylab reads it.
std::optional<std::string> imageSizeProblem(std::int64_t width, std::int64_t height);

struct ImageSize {
    int width = 0;
    int height = 0;
};

// Width and height from the header of an encoded PNG or JPEG in memory; nullopt for other formats
// or an unreadable header (the decoder then reports it).
std::optional<ImageSize> encodedImageSize(const unsigned char* bytes, std::size_t size);

} // namespace raylab
