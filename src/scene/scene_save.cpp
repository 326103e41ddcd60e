#include "scene/scene_save.h"

#include "scene/scene_error.h"
#include "scene/scene_writer.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

namespace raylab {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void cannotWrite(const fs::path& file, const std::string& why) {
    throw SceneError(file.string() + ": error: cannot write: " + why);
}

// Writes `text` to a new file and flushes it to the disk; returns the errno of a failure, 0 on success.
int writeDurably(const fs::path& path, const std::string& text) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) return errno;
    int error = 0;
    for (std::size_t done = 0; done < text.size() && error == 0;) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno != EINTR) error = errno;
        if (n > 0) done += std::size_t(n);
    }
    if (error == 0 && ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    return error;
}

} // namespace

fs::path backupPath(const fs::path& file) {
    fs::path bak = file;
    bak += ".bak";
    return bak;
}

void saveSceneFile(const Scene& scene, const fs::path& file) {
    std::string text;
    try {
        text = sceneToJson(scene, file).dump(2) + "\n";
    } catch (const nlohmann::json::exception&) {
        cannotWrite(file, "a name in the scene is not valid UTF-8");
    } catch (const fs::filesystem_error& e) {
        cannotWrite(file, e.code().message());
    }
    fs::path tmp = file;
    tmp.replace_filename("." + file.filename().string() + ".tmp");
    if (const int error = writeDurably(tmp, text)) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        cannotWrite(file, std::strerror(error));
    }
    // A hard link keeps the previous file as it was without copying it; copy where links are refused.
    const fs::path bak = backupPath(file);
    std::error_code ec;
    const bool replacing = fs::exists(file, ec);
    if (replacing) {
        const fs::file_status previous = fs::status(file, ec);
        if (!ec) fs::permissions(tmp, previous.permissions(), ec);   // the new file keeps the old one's mode
        fs::remove(bak, ec);
        fs::create_hard_link(file, bak, ec);
        if (ec) fs::copy_file(file, bak, fs::copy_options::overwrite_existing, ec);
        if (ec) {
            std::error_code ignored;
            fs::remove(tmp, ignored);
            cannotWrite(file, "cannot keep the previous file as " + bak.string() + ": " + ec.message());
        }
    }
    fs::rename(tmp, file, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        if (replacing) fs::remove(bak, ignored);   // the previous file is still in place
        cannotWrite(file, ec.message());
    }
    if (replacing) fs::remove(bak, ec);
}

} // namespace raylab
