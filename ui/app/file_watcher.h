#pragma once
// Notices when a file changes on disk (modification time or size), by polling: cheap for the one
// scene file the viewer shows, and needs nothing platform-specific.
#include <cstdint>
#include <filesystem>
#include <optional>

namespace raylab::ui {

class FileWatcher {
public:
    void watch(const std::filesystem::path& file);   // remembers the file's current state
    void clear() { file_.clear(); }
    // True once per change (and a file that vanished and came back counts as a change).
    bool changed();
    const std::filesystem::path& file() const { return file_; }

private:
    struct Stamp {
        std::filesystem::file_time_type time;
        std::uintmax_t size = 0;
        bool operator==(const Stamp&) const = default;
    };
    static std::optional<Stamp> stampOf(const std::filesystem::path& file);
    std::filesystem::path file_;
    std::optional<Stamp> stamp_;
};

} // namespace raylab::ui
