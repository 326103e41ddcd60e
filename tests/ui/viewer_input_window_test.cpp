// Keys and dropped files through the real `raylab` window under Xvfb (tests/ui/viewer_run.h): the
// script's `key` goes through the window's own key handling (F12 screenshot, F9 export, Space
// pause, R reset, F5 reload shaders) and `drop` through its drop callback (a scene file opens; a
// broken one leaves the previous scene and image with the error shown). One viewer run.
// Skips (with the reason) only where Xvfb is not installed.
#include "ui/viewer_run.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>

namespace raylab::ui {
namespace {

using namespace test_run;

const std::string kScene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json";
const std::string kDropped = std::string(RAYLAB_SOURCE_DIR) + "/scenes/lesson_one_sphere.json";

// The samples per pixel a screenshot's log line reports.
int loggedSpp(const std::string& log, const std::string& file) {
    const std::regex line("screenshot " + file + R"( \([^)]*, (\d+) spp\))");
    std::smatch m;
    return std::regex_search(log, m, line) ? std::stoi(m[1].str()) : -1;
}

TEST(ViewerInputWindow, KeysAndDroppedFilesGoThroughTheWindow) {
    RAYLAB_START_XVFB(x);
    const fs::path dir = test::windowTestDir("raylab_viewer_input_");
    std::ofstream(dir / "broken.json") << "{\n  \"render\": {\n    \"max_bounces\": -1\n  }\n}\n";
    const std::string d = dir.string();
    ViewerOptions small;
    small.scale = 0.25f;   // 160 x 90 traced
    small.windowWidth = 960;
    small.windowHeight = 600;
    // F12 and F9 write raylab-screenshot.png and raylab-render.exr into the working directory
    // (the run's directory). Tracing stops at the 4 spp target, so images are deterministic.
    const ViewerRun run = runViewer(x, dir,
                                    "set render.spp 4\nwait-spp 4\nkey f12\nscreenshot " + d + "/converged.png\n"
                                    "key f9\nexport " + d + "/converged.exr\n"
                                    // Pause, then reset: the image stays empty while paused.
                                    "key space\nkey r\nwait-frames 5\nscreenshot " + d + "/paused.png\n"
                                    "key space\nwait-spp 4\nscreenshot " + d + "/resumed.png\n"
                                    "key f5\nwait-spp 4\n"
                                    "drop " + kDropped + "\nset render.spp 4\nwait-spp 4\nscreenshot " + d + "/dropped.png\n"
                                    "export " + d + "/dropped.exr\n"
                                    "drop " + d + "/broken.json\nwait-frames 2\nscreenshot " + d + "/broken.png\n"
                                    "export " + d + "/after-broken.exr\nquit\n",
                                    kScene, small);
    ASSERT_EQ(run.status, 0) << "a drop that fails is the window's error, not the script's\n" << run.log;
    for (const char* name : {"raylab-screenshot", "converged", "paused", "resumed", "dropped", "broken"})
        ASSERT_EQ(run.shots.count(name), 1u) << name << "\n" << run.log;

    const Shot& converged = run.shots.at("converged");
    {
        SCOPED_TRACE("F12: the window as PNG, as the screenshot command saves it");
        const Shot& f12 = run.shots.at("raylab-screenshot");
        EXPECT_EQ(loggedSpp(run.log, "raylab-screenshot.png"), 4);
        EXPECT_EQ(f12.image.width, 960);
        EXPECT_EQ(imageDifference(f12, converged), 0.0);
    }
    {
        SCOPED_TRACE("F9: the render as EXR (linear), as the export command writes it");
        EXPECT_NE(run.log.find("exported raylab-render.exr (4 spp)"), std::string::npos) << run.log;
        ASSERT_TRUE(fs::exists(dir / "raylab-render.exr"));
        EXPECT_EQ(readImage(dir / "raylab-render.exr").rgba, readImage(dir / "converged.exr").rgba);
    }
    {
        SCOPED_TRACE("Space pauses, R resets: no samples while paused; Space resumes to the same image");
        EXPECT_EQ(loggedSpp(run.log, d + "/paused.png"), 0) << run.log;
        EXPECT_EQ(loggedSpp(run.log, d + "/resumed.png"), 4) << run.log;
        EXPECT_EQ(imageDifference(run.shots.at("resumed"), converged), 0.0);
    }
    EXPECT_NE(run.log.find("reloaded the shaders (F5)"), std::string::npos) << run.log;
    const Shot& dropped = run.shots.at("dropped");
    {
        SCOPED_TRACE("a dropped scene file opens");
        EXPECT_NE(run.log.find("opened " + kDropped), std::string::npos) << run.log;
        EXPECT_GT(imageDifference(dropped, converged), 0.05);
    }
    {
        SCOPED_TRACE("a dropped broken file keeps the previous scene and image, with the error shown");
        EXPECT_NE(run.log.find("broken.json:3:"), std::string::npos) << run.log;
        EXPECT_EQ(errorBannerPixels(dropped), 0);
        EXPECT_GT(errorBannerPixels(run.shots.at("broken")), 50);
        EXPECT_EQ(readImage(dir / "dropped.exr").rgba, readImage(dir / "after-broken.exr").rgba);
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
}

} // namespace
} // namespace raylab::ui
