#include "io/resource_directory.h"

namespace raylab {

std::filesystem::path resourceDirectory(const char* override, const char* name, const char* marker,
                                        const std::filesystem::path& sourceDir) {
    if (override && *override) return override;
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const std::filesystem::path installed = exe.parent_path().parent_path() / "share" / "raylab" / name;
        if (std::filesystem::exists(installed / marker)) return installed;
    }
    return sourceDir;
}

} // namespace raylab
