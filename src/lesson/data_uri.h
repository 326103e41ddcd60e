#pragma once
// A file as an RFC 2397 data: URI (base64, RFC 4648), so a page carries its pictures inside.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace raylab {

std::string base64(std::string_view bytes);

// "data:image/png;base64,..." for a .png, .jpg, .jpeg, .gif or .svg file; nullopt when it cannot be read.
std::optional<std::string> fileDataUri(const std::filesystem::path& file);

} // namespace raylab
