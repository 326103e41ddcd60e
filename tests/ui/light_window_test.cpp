// The lights in the real `raylab` window under Xvfb: scenes/lights.json's gizmos land on the lines
// the model projects, and a light selected through the script and edited through `selected.KEY`
// changes the traced image. Skips (with the reason) only where Xvfb is not installed.
#include "app/light_gizmo.h"
#include "io/image_io.h"
#include "scene/scene_loader.h"
#include "ui/viewer_run.h"
#include "ui/xvfb.h"

#include <gtest/gtest.h>

#include <numeric>

namespace raylab::ui {
namespace {

using namespace test_run;

double imageSum(const Image& img) { return std::accumulate(img.rgba.begin(), img.rgba.end(), 0.0); }

TEST(LightWindow, GizmosLandOnTheLightsAndAnEditedLightChangesTheImage) {
    RAYLAB_START_XVFB(x);
    const fs::path dir = test::windowTestDir("raylab_light_window_");
    const std::string d = dir.string(), scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/lights.json";
    const ViewerRun run = runViewer(x, dir,
                                    "wait-spp 2\npause\nexport " + d + "/before.exr\nscreenshot " + d + "/before.png\n"
                                    "overlay lights on\nscreenshot " + d + "/gizmos.png\noverlay lights off\n"
                                    "select-light 0\nset selected.intensity 60\nresume\nwait-spp 2\npause\n"
                                    "export " + d + "/after.exr\nquit\n",
                                    scene);
    ASSERT_EQ(run.status, 0) << run.log;
    ASSERT_EQ(run.shots.count("gizmos"), 1u) << run.log;
    {
        SCOPED_TRACE("every pixel the gizmos change lies on a line of the model's gizmos");
        const Scene s = loadScene(scene);
        const int w = s.render.width / 2, h = s.render.height / 2;   // --scale 0.5
        std::vector<Segment> lines;
        for (int i = 0; i < int(s.lights.size()); ++i) {
            const std::vector<Segment> g = lightGizmo(s, w, h, i);
            EXPECT_FALSE(g.empty()) << "light " << i << " is in view";
            lines.insert(lines.end(), g.begin(), g.end());
        }
        const OverlayPixels p = overlayPixels(run.shots.at("before"), run.shots.at("gizmos"), toWindow(run.shots.at("gizmos"), lines, w, h));
        EXPECT_GT(p.changed, 100);
        EXPECT_EQ(p.far, 0);
    }
    {
        SCOPED_TRACE("ten times the point light's intensity brightens the image");
        const Image before = readImage(dir / "before.exr"), after = readImage(dir / "after.exr");
        ASSERT_EQ(before.rgba.size(), after.rgba.size());
        EXPECT_GT(imageSum(after), imageSum(before) * 1.05);
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
}

} // namespace
} // namespace raylab::ui
