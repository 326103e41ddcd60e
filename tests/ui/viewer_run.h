#pragma once
// Runs the real `raylab` program under Xvfb with an automation script and collects the screenshots
// it saves (tests/ui/viewer_window_test.cpp, viewer_debug_window_test.cpp).
#include "io/image_io.h"
#include "ui/xvfb.h"

#include <glm/glm.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

namespace raylab::ui::test_run {

namespace fs = std::filesystem;

struct Shot {
    Image image;        // the window, top row first
    float x = 0, y = 0, w = 0, h = 0;   // where the traced image lies in it
};

struct ViewerRun {
    int status = -1;
    std::string log;
    std::map<std::string, Shot> shots;
};

inline std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Runs the viewer with `script` at resolution scale 0.5 (320 x 180 traced) in a 1280 x 800 window.
inline ViewerRun runViewer(const ::raylab::test::Xvfb& x, const fs::path& dir, const std::string& script, const std::string& scene) {
    fs::create_directories(dir);
    std::ofstream(dir / "script.txt") << script;
    const std::string cmd = "DISPLAY=" + x.display() + " " RAYLAB_VIEWER_EXE " '" + scene + "' --ini '' --scale 0.5 --window 1280 800 --script '" +
                            (dir / "script.txt").string() + "' --script-timeout 240 > '" + (dir / "log.txt").string() + "' 2>&1";
    ViewerRun run;
    const int raw = std::system(cmd.c_str());
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    run.log = readText(dir / "log.txt");
    const std::regex line(R"(screenshot (\S+) \(\d+x\d+; image at ([\d.]+) ([\d.]+) size ([\d.]+) ([\d.]+),)");
    for (std::sregex_iterator it(run.log.begin(), run.log.end(), line), end; it != end; ++it) {
        Shot s;
        s.image = readImage((*it)[1].str());
        s.x = std::stof((*it)[2].str());
        s.y = std::stof((*it)[3].str());
        s.w = std::stof((*it)[4].str());
        s.h = std::stof((*it)[5].str());
        run.shots[fs::path((*it)[1].str()).stem().string()] = std::move(s);
    }
    return run;
}

// Mean absolute difference of two shots over the traced image's area.
inline double imageDifference(const Shot& a, const Shot& b) {
    double sum = 0;
    int n = 0;
    for (int y = int(a.y) + 1; y < int(a.y + a.h) - 1; ++y)
        for (int x = int(a.x) + 1; x < int(a.x + a.w) - 1; ++x) {
            const glm::vec3 d = glm::abs(a.image.rgb(x, y) - b.image.rgb(x, y));
            sum += double(d.x + d.y + d.z) / 3.0;
            ++n;
        }
    return sum / n;
}

// Where the first-use layout of a 1280 x 800 window puts a 16:9 traced image
// (ui/panels/viewport_panel.cpp, drawWorkspace).
constexpr float kImageX = 332.0f, kImageY = 121.25f, kImageW = 616.0f, kImageH = 346.5f;

} // namespace raylab::ui::test_run
