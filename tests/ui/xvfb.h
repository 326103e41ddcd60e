#pragma once
// A private X server for window tests: Xvfb picks a free display itself (-displayfd) and is
// stopped (its process id only) when the object goes away.
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace raylab::test {

inline std::string findProgram(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    for (std::size_t start = 0;;) {
        const std::size_t end = dirs.find(':', start);
        const std::filesystem::path p = std::filesystem::path(dirs.substr(start, end - start)) / name;
        if (::access(p.c_str(), X_OK) == 0) return p.string();
        if (end == std::string::npos) return "";
        start = end + 1;
    }
}

class Xvfb {
public:
    // Empty display() when Xvfb is missing or did not start.
    Xvfb() {
        const std::string exe = findProgram("Xvfb");
        if (exe.empty()) return;
        int fds[2];
        if (::pipe(fds) != 0) return;
        pid_ = ::fork();
        if (pid_ == 0) {
            ::close(fds[0]);
            const std::string fd = std::to_string(fds[1]);
            ::execl(exe.c_str(), "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp",
                    static_cast<char*>(nullptr));
            ::_exit(127);
        }
        ::close(fds[1]);
        char buf[32] = {};
        std::string number;
        for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) {
            number.append(buf, std::size_t(n));
            if (number.find('\n') != std::string::npos) break;
        }
        ::close(fds[0]);
        while (!number.empty() && (number.back() == '\n' || number.back() == ' ')) number.pop_back();
        if (!number.empty()) display_ = ":" + number;
    }
    ~Xvfb() {
        if (pid_ > 0) {
            ::kill(pid_, SIGTERM);
            ::waitpid(pid_, nullptr, 0);
        }
    }
    Xvfb(const Xvfb&) = delete;
    Xvfb& operator=(const Xvfb&) = delete;
    const std::string& display() const { return display_; }

private:
    pid_t pid_ = -1;
    std::string display_;
};

// A fresh scratch folder for one window test: the temp directory / (prefix + process id).
inline std::filesystem::path windowTestDir(const std::string& prefix) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace raylab::test

// In a test body: skips the test when Xvfb is not installed, otherwise starts one as NAME and
// fails the test when it does not come up.
#define RAYLAB_START_XVFB(NAME)                                                                           \
    if (::raylab::test::findProgram("Xvfb").empty())                                                      \
        GTEST_SKIP() << "Xvfb is not installed (cmake/install-deps.sh installs it)";                      \
    ::raylab::test::Xvfb NAME;                                                                            \
    ASSERT_FALSE(NAME.display().empty()) << "Xvfb did not start"
