// The pixel path inspector in the real viewer under Xvfb: `inspect X Y` records a pixel's paths
// and the viewport draws them over the image with the tracer's camera: every pixel the overlay
// changes lies on a line of the exported paths projected by the same maths, and there are many.
#include "app/inspection.h"
#include "inspect/path_export.h"
#include "io/image_io.h"
#include "scene/scene_loader.h"
#include "ui/xvfb.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace raylab::ui {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float t = glm::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-9f), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

TEST(InspectorWindow, InspectDrawsThePixelsPathsOverTheImage) {
    RAYLAB_START_XVFB(x);
    const fs::path dir = test::windowTestDir("raylab_inspector_window_");
    const std::string scenePath = std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json";
    Scene scene = loadScene(scenePath);
    // `inspect X Y` takes pixels of the scene's image (640×360); the viewer traces at scale 0.5
    // (320×180), where the inspected pixel and the overlay live.
    const auto target = projectPoint(scene, scene.render.width, scene.render.height, scene.spheres[1].center);
    ASSERT_TRUE(target);
    const int sceneX = int(target->x), sceneY = int(target->y);
    const int px = sceneX / 2, py = sceneY / 2;
    scene.render.width = 320;
    scene.render.height = 180;
    const std::string d = dir.string();
    std::ofstream(dir / "script.txt") << "wait-spp 2\npause\nscreenshot " << d << "/before.png\n"
                                      << "inspect " << sceneX << " " << sceneY << " 6\npanel inspector off\n"
                                      << "inspect-export " << d << "/paths.json\nwait-frames 2\n"
                                      << "screenshot " << d << "/paths.png\nquit\n";
    const std::string cmd = "DISPLAY=" + x.display() + " " RAYLAB_VIEWER_EXE " '" + scenePath +
                            "' --ini '' --scale 0.5 --window 1280 800 --script '" + (dir / "script.txt").string() +
                            "' --script-timeout 240 > '" + (dir / "log.txt").string() + "' 2>&1";
    const int raw = std::system(cmd.c_str());
    const std::string log = slurp(dir / "log.txt");
    ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << log;
    ASSERT_NE(log.find("inspected pixel (" + std::to_string(px) + ", " + std::to_string(py) + "): 6 paths"),
              std::string::npos) << log;

    const std::regex shotLine(R"(screenshot (\S+) \(\d+x\d+; image at ([\d.]+) ([\d.]+) size ([\d.]+) ([\d.]+),)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(log, m, shotLine)) << log;
    const float ix = std::stof(m[2].str()), iy = std::stof(m[3].str()), iw = std::stof(m[4].str()), ih = std::stof(m[5].str());
    const Image before = readImage(dir / "before.png"), after = readImage(dir / "paths.png");

    std::ifstream in(dir / "paths.json");
    const auto paths = pathsFromJson(nlohmann::json::parse(in));
    ASSERT_EQ(paths.size(), 6u);
    const PathOverlay overlay = pathOverlay(scene, 320, 180, paths, PathOverlaySettings{});
    const auto toWindow = [&](ImagePoint p) { return glm::vec2(ix + p.x / 320.0f * iw, iy + p.y / 180.0f * ih); };
    // Reach of what ImGui draws: 2-pixel lines (+1 px anti-aliasing feather), hit dots of radius 3
    // with an outline, the pixel's marker; plus half a pixel diagonal.
    const auto near = [&](glm::vec2 p) {
        for (const PathLine& l : overlay.lines)
            if (distanceToSegment(p, toWindow(l.segment.a), toWindow(l.segment.b)) <= 1.0f + 1.0f + 0.71f) return true;
        for (const PathDot& dot : overlay.hits)
            if (glm::length(p - toWindow(dot.point)) <= 3.0f + 1.5f + 0.71f) return true;
        const glm::vec2 a = toWindow({float(px), float(py)}) - 2.0f, b = toWindow({float(px + 1), float(py + 1)}) + 2.0f;
        for (auto [s, e] : {std::pair{a, glm::vec2(b.x, a.y)}, std::pair{glm::vec2(b.x, a.y), b},
                            std::pair{b, glm::vec2(a.x, b.y)}, std::pair{glm::vec2(a.x, b.y), a}})
            if (distanceToSegment(p, s, e) <= 0.5f + 1.0f + 0.71f) return true;
        return false;
    };
    int changed = 0, far = 0;
    for (int y = int(iy) + 1; y < int(iy + ih) - 1; ++y)
        for (int xx = int(ix) + 1; xx < int(ix + iw) - 1; ++xx) {
            if (glm::length(after.rgb(xx, y) - before.rgb(xx, y)) < 0.02f) continue;
            ++changed;
            if (!near(glm::vec2(float(xx) + 0.5f, float(y) + 0.5f))) ++far;
        }
    EXPECT_GT(changed, 150) << "no path overlay drawn";
    EXPECT_EQ(far, 0) << "of " << changed << " changed pixels";
    std::error_code ec;
    fs::remove_all(dir, ec);
}

} // namespace
} // namespace raylab::ui
