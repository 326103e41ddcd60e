#pragma once
// Runs the real `raylab` program under Xvfb with an automation script and collects the screenshots
// it saves (tests/ui/viewer_window_test.cpp, viewer_debug_window_test.cpp).
#include "io/image_io.h"
#include "ui/xvfb.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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

struct ViewerOptions {
    float scale = 0.5f;               // resolution scale of the traced image
    int windowWidth = 1280, windowHeight = 800;
    int scriptTimeout = 240;          // seconds
    std::string extraArgs;            // appended to the command line as they are
};

// Runs the viewer with `script` (at scale 0.5, 320 x 180 traced for the default scene, in a
// 1280 x 800 window unless `options` say otherwise) in `dir` as its working directory: files the
// viewer names itself (F12's raylab-screenshot.png, F9's raylab-render.exr) land there.
inline ViewerRun runViewer(const ::raylab::test::Xvfb& x, const fs::path& dir, const std::string& script, const std::string& scene,
                           const ViewerOptions& options = {}) {
    fs::create_directories(dir);
    std::ofstream(dir / "script.txt") << script;
    const std::string cmd = "cd '" + dir.string() + "' && DISPLAY=" + x.display() + " " RAYLAB_VIEWER_EXE " '" + scene +
                            "' --ini '' --scale " + std::to_string(options.scale) + " --window " +
                            std::to_string(options.windowWidth) + " " + std::to_string(options.windowHeight) + " --script '" +
                            (dir / "script.txt").string() + "' --script-timeout " + std::to_string(options.scriptTimeout) +
                            " " + options.extraArgs + " > '" + (dir / "log.txt").string() + "' 2>&1";
    ViewerRun run;
    const int raw = std::system(cmd.c_str());
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    run.log = readText(dir / "log.txt");
    const std::regex line(R"(screenshot (\S+) \(\d+x\d+; image at ([\d.]+) ([\d.]+) size ([\d.]+) ([\d.]+),)");
    for (std::sregex_iterator it(run.log.begin(), run.log.end(), line), end; it != end; ++it) {
        Shot s;
        s.image = readImage(dir / (*it)[1].str());   // relative: to the viewer's working directory
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

// Image-space segments (traced pixels of a width x height image) to window pixels of a shot.
template <class Segments>
std::vector<std::pair<glm::vec2, glm::vec2>> toWindow(const Shot& s, const Segments& segments, int width, int height) {
    std::vector<std::pair<glm::vec2, glm::vec2>> out;
    for (const auto& g : segments)
        out.push_back({glm::vec2(s.x + g.a.x / float(width) * s.w, s.y + g.a.y / float(height) * s.h),
                       glm::vec2(s.x + g.b.x / float(width) * s.w, s.y + g.b.y / float(height) * s.h)});
    return out;
}

struct OverlayPixels {
    int changed = 0;   // pixels of the image area that the overlay changed
    int far = 0;       // of those, the ones no line could have touched
};

// Compares a shot with an overlay (`on`) against the same image without (`off`): every changed
// pixel must lie within reach of one of `segments` (window pixels). ImGui draws a 1-pixel line
// with a 1-pixel anti-aliasing feather on each side: coverage reaches 0.5 + 1 px from the centre
// line, and a touched pixel's centre lies within half a diagonal more.
inline OverlayPixels overlayPixels(const Shot& off, const Shot& on, const std::vector<std::pair<glm::vec2, glm::vec2>>& segments) {
    const float kReach = 0.5f + 1.0f + 0.7072f;
    auto distance = [&](glm::vec2 p) {
        float best = 1e9f;
        for (const auto& [a, b] : segments) {
            const glm::vec2 ab = b - a;
            const float t = glm::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-9f), 0.0f, 1.0f);
            best = std::min(best, glm::length(p - (a + t * ab)));
        }
        return best;
    };
    OverlayPixels r;
    for (int y = int(on.y) + 1; y < int(on.y + on.h) - 1; ++y)
        for (int x = int(on.x) + 1; x < int(on.x + on.w) - 1; ++x) {
            if (glm::length(on.image.rgb(x, y) - off.image.rgb(x, y)) < 0.02f) continue;
            ++r.changed;
            if (distance(glm::vec2(float(x) + 0.5f, float(y) + 0.5f)) > kReach) ++r.far;
        }
    return r;
}

// Red text pixels between the top of the window (below the title bar) and the image, across the
// image's width: the viewport's error banner.
inline int errorBannerPixels(const Shot& s) {
    int red = 0;
    for (int y = 20; y < int(s.y); ++y)
        for (int x = int(s.x); x < int(s.x + s.w); ++x) {
            const glm::vec3 c = s.image.rgb(x, y);
            red += c.x > 0.6f && c.y < 0.5f && c.z < 0.5f;
        }
    return red;
}

// A suite of tests that share one viewer run (ctest runs each test in its own process, and each
// run of the viewer takes seconds): the derived suite's SetUpTestSuite calls startXvfb, then sets
// run_. Suite is the derived class, so each suite has its own run.
template <class Suite>
class ViewerRunSuite : public ::testing::Test {
protected:
    // Starts Xvfb and names the run's directory; false when Xvfb is missing or did not start
    // (SetUp then skips or fails the tests with the reason).
    static bool startXvfb(const std::string& dirName) {
        if (::raylab::test::findProgram("Xvfb").empty()) return false;
        xvfb_ = new ::raylab::test::Xvfb();
        if (xvfb_->display().empty()) return false;
        dir_ = fs::temp_directory_path() / (dirName + "_" + std::to_string(::getpid()));
        return true;
    }
    static void TearDownTestSuite() {
        delete run_;
        delete xvfb_;
        std::error_code ec;
        if (!dir_.empty()) fs::remove_all(dir_, ec);
    }
    void SetUp() override {
        if (::raylab::test::findProgram("Xvfb").empty()) GTEST_SKIP() << "Xvfb is not installed (cmake/install-deps.sh installs it)";
        ASSERT_FALSE(xvfb_->display().empty()) << "Xvfb did not start";
        ASSERT_NE(run_, nullptr);
        ASSERT_EQ(run_->status, 0) << run_->log;
    }
    // A screenshot the run saved, by file stem; a failure (with the log) when it is missing.
    const Shot& shot(const std::string& name) {
        static Shot none;
        auto it = run_->shots.find(name);
        EXPECT_NE(it, run_->shots.end()) << name << " missing; log:\n" << run_->log;
        return it == run_->shots.end() ? none : it->second;
    }
    static inline ::raylab::test::Xvfb* xvfb_ = nullptr;
    static inline ViewerRun* run_ = nullptr;
    static inline fs::path dir_;
};

// Where the first-use layout of a 1280 x 800 window puts a 16:9 traced image
// (ui/panels/viewport_panel.cpp, drawWorkspace).
constexpr float kImageX = 332.0f, kImageY = 121.25f, kImageW = 616.0f, kImageH = 346.5f;

} // namespace raylab::ui::test_run
