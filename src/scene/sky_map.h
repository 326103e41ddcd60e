#pragma once
// The sky map checked when a scene is read, so a missing, garbage or oversized image is an error
// at `sky.map` rather than a failure when the renderer uploads it.
#include <filesystem>
#include <optional>
#include <string>

namespace raylab::scenefmt {

// What is wrong with `file` as a sky map ("not an image file ...", "65535x65535 is larger than ...",
// the decoder's complaint about its pixels), or nullopt when every pixel reads. The size comes
// from the header and is checked before any pixel is allocated; pixels are read a strip at a time.
std::optional<std::string> skyMapProblem(const std::filesystem::path& file);

} // namespace raylab::scenefmt
