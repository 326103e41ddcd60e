#include "app/file_watcher.h"

namespace raylab::ui {

std::optional<FileWatcher::Stamp> FileWatcher::stampOf(const std::filesystem::path& file) {
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(file, ec);
    if (ec) return std::nullopt;
    const auto size = std::filesystem::file_size(file, ec);
    if (ec) return std::nullopt;
    return Stamp{time, size};
}

void FileWatcher::watch(const std::filesystem::path& file) {
    file_ = file;
    stamp_ = stampOf(file);
}

bool FileWatcher::changed() {
    if (file_.empty()) return false;
    const auto now = stampOf(file_);
    if (!now || now == stamp_) return false;   // a file being replaced may vanish for a moment
    stamp_ = now;
    return true;
}

} // namespace raylab::ui
