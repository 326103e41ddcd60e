#include "lesson/data_uri.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>

namespace raylab {

std::string base64(std::string_view bytes) {
    static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string s;
    s.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        unsigned v = 0;
        for (std::size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) s += k <= n ? digits[(v >> (18 - 6 * k)) & 63u] : '=';
    }
    return s;
}

std::optional<std::string> fileDataUri(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const std::string mime = ext == ".png"                      ? "image/png"
                             : ext == ".jpg" || ext == ".jpeg" ? "image/jpeg"
                             : ext == ".gif"                   ? "image/gif"
                             : ext == ".svg"                   ? "image/svg+xml"
                                                               : "application/octet-stream";
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return std::nullopt;
    return "data:" + mime + ";base64," + base64(bytes);
}

} // namespace raylab
