#pragma once
// Runs raylab-render (and the other programs) as a user would, from the repository root, for the tests of its command line:
// its exit status and what it printed.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace raylab::test {

struct CliRun {
    int status = -1;   // the exit status; -1 when it did not exit (a signal)
    std::string out;
    std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A folder of this test process's own under the temporary directory.
inline std::filesystem::path scratchDir(const std::string& name) {
    std::filesystem::path d = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
}

// `exe` with `args` (shell-quoted by the caller); stdout and stderr go through files in `dir`.
inline CliRun runProgram(const std::string& exe, const std::string& args, const std::filesystem::path& dir) {
    const std::string cmd = std::string("cd '") + RAYLAB_SOURCE_DIR + "' && '" + exe + "' " + args + " > '" +
                            (dir / "out.txt").string() + "' 2> '" + (dir / "err.txt").string() + "'";
    const int raw = std::system(cmd.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir / "out.txt"), slurp(dir / "err.txt")};
}

// raylab-render with `args`.
inline CliRun runRender(const std::string& args, const std::filesystem::path& dir) { return runProgram(RAYLAB_RENDER_EXE, args, dir); }

} // namespace raylab::test
