// The Teach window in the real `raylab` under Xvfb: a lesson opened with --lesson, a presenter key
// applying step 1 (its overlay drawn, its button highlighted), a step applied by number, the A/B
// split screen whose halves are raylab-render's images of each side (one side a debug view, the
// other the render), the UI scale remembered in the layout file, and the self-test passing on the
// X server's GL driver.
#include "io/image_io.h"
#include "render/render_helpers.h"
#include "ui/xvfb.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace raylab::ui {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

int run(const std::string& cmd) {
    const int raw = std::system(cmd.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
};

// "screenshot PATH (WxH; image at X Y size W H, ...)" lines of the viewer's log.
std::map<std::string, Rect> shots(const std::string& log) {
    std::map<std::string, Rect> out;
    const std::regex line(R"(screenshot (\S+) \(\d+x\d+; image at ([\d.]+) ([\d.]+) size ([\d.]+) ([\d.]+),)");
    for (std::sregex_iterator it(log.begin(), log.end(), line), end; it != end; ++it)
        out[fs::path((*it)[1].str()).stem().string()] =
            Rect{std::stof((*it)[2].str()), std::stof((*it)[3].str()), std::stof((*it)[4].str()), std::stof((*it)[5].str())};
    return out;
}

int countPixels(const Image& img, int x0, int y0, int x1, int y1, bool (*test)(glm::vec3)) {
    int n = 0;
    for (int y = std::max(y0, 0); y < std::min(y1, img.height); ++y)
        for (int x = std::max(x0, 0); x < std::min(x1, img.width); ++x) n += test(img.rgb(x, y));
    return n;
}

} // namespace

TEST(TeachWindow, ALessonStepsTheSplitScreenMatchesTheRendererAndTheSelfTestPasses) {
    RAYLAB_START_XVFB(x);
    const fs::path dir = test::windowTestDir("raylab_teach_window_");
    const std::string d = dir.string();
    const std::string src = RAYLAB_SOURCE_DIR;
    std::ofstream(dir / "script.txt") << "wait-frames 2\nkey page-down\nwait-spp 2\npause\nscreenshot " << d << "/step1.png\n"
                                      << "resume\nlesson-step 2\nwait-spp 2\n"
                                      << "set render.spp 4\nsplit samples\nsplit-a render.max_bounces 1\n"
                                      << "split-b render.max_bounces 4\nsplit-divider 0.5\nwait-spp 4\npause\n"
                                      << "screenshot " << d << "/split.png\nexport " << d << "/split.exr\nsplit off\n"
                                      << "resume\nsplit samples\nsplit-a debug-view ao\nwait-spp 4\npause\n"
                                      << "export " << d << "/ao_split.exr\nsplit off\nresume\n"
                                      << "ui-scale 1.5\nwait-frames 2\nself-test\nquit\n";
    const std::string cmd = "DISPLAY=" + x.display() + " " RAYLAB_VIEWER_EXE " --lesson '" + src +
                            "/lessons/05-ray-box-bvh.md' --ini '" + d + "/layout.ini' --scale 0.5 --window 1280 800 --script '" + d +
                            "/script.txt' --script-timeout 400 > '" + d + "/log.txt' 2>&1";
    const int status = run(cmd);
    const std::string log = readText(dir / "log.txt");
    ASSERT_EQ(status, 0) << log;

    // The presenter key applied step 1: the lesson's scene reopened, every box drawn (yellow), the
    // step's button highlighted (orange) in the Teach window on the left.
    EXPECT_NE(log.find("lesson Lesson 5"), std::string::npos) << log;
    const auto rects = shots(log);
    ASSERT_EQ(rects.count("step1"), 1u) << log;
    const Rect r = rects.at("step1");
    const Image step1 = readImage(dir / "step1.png");
    EXPECT_GT(countPixels(step1, int(r.x), int(r.y), int(r.x + r.w), int(r.y + r.h),
                          [](glm::vec3 c) { return c.x > 0.8f && c.y > 0.8f && c.z < 0.2f; }),
              100)
        << "step 1 turns on the box overlay";
    EXPECT_GT(countPixels(step1, 0, 0, 330, 800,
                          [](glm::vec3 c) { return c.x > 0.5f && c.y > 0.15f && c.y < 0.65f && c.z < 0.15f && c.x - c.y > 0.2f; }),
              200)
        << "the current step's button is highlighted";

    // The split screen's halves are raylab-render's images of each side (same seed, 4 spp).
    auto render = [&](const std::string& name, int bounces) {
        const std::string out = d + "/" + name + ".exr";
        EXPECT_EQ(run(std::string(RAYLAB_RENDER_EXE) + " '" + src + "/scenes/default.json' --width 320 --height 180 --spp 4 --set render.max_bounces=" +
                      std::to_string(bounces) + " -q -o '" + out + "' > /dev/null 2>&1"),
                  0);
        return readImage(out);
    };
    const Image a = render("a", 1), b = render("b", 4);
    const Image split = readImage(dir / "split.exr");
    ASSERT_EQ(split.width, 320);
    ASSERT_EQ(a.width, 320);
    int wrong = 0;
    for (int y = 0; y < 180; ++y)
        for (int px = 0; px < 320; ++px) wrong += split.rgb(px, y) != (px < 160 ? a : b).rgb(px, y);
    EXPECT_EQ(wrong, 0) << "left half = A (max_bounces 1), right half = B (max_bounces 4)";

    // A debug view on one side: the traced ambient occlusion (raylab-render --debug-view ao, a
    // grey in [0, 1]) beside the render.
    const std::string aoFile = d + "/ao.exr", beautyFile = d + "/beauty.exr";
    const std::string scene = " '" + src + "/scenes/default.json' --width 320 --height 180 --spp 4 -q -o '";
    ASSERT_EQ(run(std::string(RAYLAB_RENDER_EXE) + scene + aoFile + "' --debug-view ao > /dev/null 2>&1"), 0);
    ASSERT_EQ(run(std::string(RAYLAB_RENDER_EXE) + scene + beautyFile + "' > /dev/null 2>&1"), 0);
    const Image ao = readImage(aoFile), beauty = readImage(beautyFile), aoSplit = readImage(dir / "ao_split.exr");
    ASSERT_EQ(aoSplit.width, 320);
    int wrongAo = 0, notGrey = 0;
    for (int y = 0; y < 180; ++y)
        for (int px = 0; px < 320; ++px) {
            const glm::vec3 c = aoSplit.rgb(px, y);
            wrongAo += c != (px < 160 ? ao : beauty).rgb(px, y);
            if (px < 160) notGrey += !(c.x >= 0.0f && c.x <= 1.0f && c.y == c.x && c.z == c.x);
        }
    EXPECT_EQ(wrongAo, 0) << "left half = the ao view, right half = the render";
    EXPECT_EQ(notGrey, 0);
    EXPECT_GT(test::rmse(ao, beauty), 0.05) << "the two sides differ";

    // UI scale remembered; the self-test passed on this driver (a failure would fail the script).
    EXPECT_NE(readText(dir / "layout.ini").find("[Raylab][Classroom]\nUiScale=1.500"), std::string::npos);
    EXPECT_NE(log.find("self-test: PASS furnace"), std::string::npos) << log;
    EXPECT_NE(log.find("self-test: PASS GGX VNDF a=0.3 cos=0.5"), std::string::npos) << log;
    std::error_code ec;
    fs::remove_all(dir, ec);
}

} // namespace raylab::ui
