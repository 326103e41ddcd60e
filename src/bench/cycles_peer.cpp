#include "bench/cycles_peer.h"

#include "io/image_io.h"

#include <array>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace raylab {
namespace fs = std::filesystem;
namespace {

// Runs a shell command, returns its exit status and combined output.
int runCommand(const std::string& command, std::string& output) {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>&1").c_str(), "r"), pclose);
    if (!pipe) return -1;
    std::array<char, 4096> buf{};
    while (fgets(buf.data(), int(buf.size()), pipe.get())) output += buf.data();
    return pclose(pipe.release());
}

std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

} // namespace

bool blenderAvailable(std::string* why) {
    std::string out;
    if (runCommand("blender --version", out) != 0 || out.find("Blender") == std::string::npos) {
        if (why) *why = "blender not found (apt-get install blender)";
        return false;
    }
    return true;
}

CyclesRun runCycles(const fs::path& script, int samples, int threads, int seed, const fs::path& workDir,
                    double adaptiveThreshold) {
    const bool adaptive = adaptiveThreshold >= 0.0;
    char threshold[32];
    std::snprintf(threshold, sizeof threshold, "%.9g", adaptiveThreshold);
    fs::create_directories(workDir);
    const fs::path out = workDir / ("cycles_" + std::to_string(samples) + "_" + std::to_string(seed) +
                                    (adaptive ? std::string("_adaptive_") + threshold : std::string()) + ".exr");
    std::string log;
    const std::string cmd = "blender -b --factory-startup --python " + quote(script.string()) +
                            " -- --samples " + std::to_string(samples) + " --threads " + std::to_string(threads) +
                            " --seed " + std::to_string(seed) +
                            (adaptive ? std::string(" --adaptive-threshold ") + threshold : std::string()) +
                            " --output " + quote(out.string());
    const int status = runCommand(cmd, log);
    const auto at = log.find("RAYLAB_RENDER_SECONDS ");
    if (status != 0 || at == std::string::npos || !fs::exists(out))
        throw std::runtime_error("Cycles run failed: " + cmd + "\n" +
                                 log.substr(log.size() > 2000 ? log.size() - 2000 : 0));
    CyclesRun run;
    run.seconds = std::stod(log.substr(at + 22));
    run.image = readImage(out);
    fs::remove(out);
    return run;
}

} // namespace raylab
