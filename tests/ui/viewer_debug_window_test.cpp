// The viewer's inspection tools in a real window under Xvfb (tests/ui/viewer_run.h): click-to-focus
// through the Camera panel's mode, the BVH-level overlay, and the box / triangle heat maps with
// their legend. Skips (with the reason) only where Xvfb is not installed.
#include "app/bvh_overlay.h"
#include "app/view_geometry.h"
#include "scene/scene_loader.h"
#include "ui/viewer_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace raylab::ui {
namespace {

using namespace test_run;

// Traced image size at --scale 0.5 for the 640 x 360 default scene.
constexpr int kW = 320, kH = 180;

class ViewerDebugWindowTest : public ViewerRunSuite<ViewerDebugWindowTest> {
protected:
    static void SetUpTestSuite() {
        if (!startXvfb("raylab_viewer_debug_window")) return;
        const std::string scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json";
        const std::string terrain = std::string(RAYLAB_SOURCE_DIR) + "/scenes/displaced_terrain.json";
        const std::string d = dir_.string();
        const Scene s = loadScene(scene);
        const auto c = projectPoint(s, kW, kH, s.spheres[1].center);   // the white sphere
        const float clickX = kImageX + c->x / float(kW) * kImageW, clickY = kImageY + c->y / float(kH) * kImageH;
        run_ = new ViewerRun(runViewer(
            *xvfb_, dir_,
            // The albedo view through a lens focused far behind everything, then click-to-focus on
            // the white sphere, then the pinhole image as the sharp reference (64 spp each). The
            // albedo view has no path-tracing noise, only the pixel and lens sampling: the
            // comparison sees the blur and little else. Then the beauty image for the overlay.
            "debug-view albedo\nset camera.aperture 0.3\nset camera.focus_distance 40\nset render.spp 64\nwait-spp 64\n"
            "export " + d + "/blurred.exr\n"
            "focus-mode on\nclick " + std::to_string(clickX) + " " + std::to_string(clickY) + "\nwait-spp 64\n"
            "export " + d + "/focused.exr\n"
            "set camera.aperture 0\nwait-spp 64\nexport " + d + "/pinhole.exr\n"
            "debug-view beauty\nset render.spp 16\nwait-spp 16\npause\nscreenshot " + d + "/pinhole.png\n"
            "overlay bvh on\nbvh-depth 1\nscreenshot " + d + "/bvh.png\noverlay bvh off\n"
            "open " + terrain + "\nset render.spp 4\nresume\nwait-spp 4\nscreenshot " + d + "/terrain.png\n"
            "debug-view boxes\nresume\nwait-spp 4\npause\nscreenshot " + d + "/boxes.png\nexport " + d + "/boxes.exr\n"
            "debug-view triangles\nwait-frames 2\nscreenshot " + d + "/triangles.png\nquit\n",
            scene));
    }
    void checkBvhOverlay();
    void checkHeatMaps();
};

// One test: ctest runs every test in its own process, and each would start the viewer again.
TEST_F(ViewerDebugWindowTest, ClickToFocusBvhOverlayAndHeatMaps) {
    SCOPED_TRACE("click-to-focus makes the clicked sphere sharp");
    ASSERT_NE(run_->log.find("focus distance "), std::string::npos) << run_->log;
    EXPECT_EQ(run_->log.find("picked object"), std::string::npos) << "in focus mode a click focuses, it does not pick";
    const Image blurred = readImage(dir_ / "blurred.exr");
    const Image focused = readImage(dir_ / "focused.exr");
    const Image sharp = readImage(dir_ / "pinhole.exr");
    ASSERT_EQ(blurred.width, kW);
    ASSERT_EQ(sharp.width, kW);
    // The white sphere's silhouette (from the tracer's camera maths): pixels within 3 of a pixel
    // whose neighbour is on the other side of the outline. There the lens blur shows most.
    const Scene s = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json");
    std::vector<int> mask(std::size_t(kW * kH));
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            mask[std::size_t(y * kW + x)] = pickObject(s, kW, kH, ImagePoint{float(x) + 0.5f, float(y) + 0.5f}) == 1;
    auto onRing = [&](int x, int y) {
        for (int dy = -3; dy <= 3; ++dy)
            for (int dx = -3; dx <= 3; ++dx) {
                const int u = std::clamp(x + dx, 0, kW - 1), v = std::clamp(y + dy, 0, kH - 1);
                if (mask[std::size_t(v * kW + u)] != mask[std::size_t(y * kW + x)]) return true;
            }
        return false;
    };
    // The pinhole render is the sharp reference: with the lens focused on the sphere its outline
    // matches the pinhole's up to noise; focused 40 units away it is smeared over ~10 pixels.
    double dFocused = 0.0, dBlurred = 0.0;
    int n = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (!onRing(x, y)) continue;
            const glm::vec3 r = sharp.rgb(x, y);
            dFocused += double(glm::length(focused.rgb(x, y) - r));
            dBlurred += double(glm::length(blurred.rgb(x, y) - r));
            ++n;
        }
    ASSERT_GT(n, 100);
    dFocused /= n;
    dBlurred /= n;
    std::printf("silhouette ring of %d pixels: mean |focused - pinhole| %.4f, |blurred - pinhole| %.4f\n", n, dFocused, dBlurred);
    EXPECT_LT(dFocused, 0.25 * dBlurred);   // measured 0.020 against 0.168
    checkBvhOverlay();
    checkHeatMaps();
}

// The same check as the object-box overlay's (viewer_window_test.cpp): every pixel the overlay
// changed lies on a projected edge of a top-level BVH box at depth 1.
void ViewerDebugWindowTest::checkBvhOverlay() {
    SCOPED_TRACE("BVH overlay pixels land on the projected boxes of the level");
    const Shot& off = shot("pinhole");
    const Shot& on = shot("bvh");
    const Scene s = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json");
    const SceneGeometry g = buildSceneGeometry(s);
    ASSERT_EQ(bvhLevel(g.topNodes, 0, 1).size(), 2u);
    const auto [changed, far] = overlayPixels(off, on, toWindow(on, topLevelBvhSegments(s, g, kW, kH, 1), kW, kH));
    EXPECT_GT(changed, 300) << "no overlay drawn";
    EXPECT_EQ(far, 0) << "of " << changed << " overlay pixels";
}

void ViewerDebugWindowTest::checkHeatMaps() {
    SCOPED_TRACE("heat maps differ from beauty and show their legend");
    const Shot& beauty = shot("terrain");
    const Shot& boxes = shot("boxes");
    const Shot& tris = shot("triangles");
    EXPECT_GT(imageDifference(beauty, boxes), 0.1);
    EXPECT_GT(imageDifference(boxes, tris), 0.01) << "two different counts";
    // The traced counts: the terrain's BVH is tested, the sky above the horizon tests no triangle.
    const Image counts = readImage(dir_ / "boxes.exr");
    EXPECT_EQ(counts.rgb(counts.width / 2, 0).y, 0.0f);
    EXPECT_GT(counts.rgb(counts.width / 2, counts.height - 1).y, 0.0f);
    // The legend at the image's bottom-left: the ramp's blue end and its red-orange end.
    int blue = 0, warm = 0;
    for (int y = int(boxes.y + boxes.h) - 40; y < int(boxes.y + boxes.h); ++y)
        for (int x = int(boxes.x); x < int(boxes.x) + 170; ++x) {
            const glm::vec3 c = boxes.image.rgb(x, y);
            blue += c.z > 0.9f && c.x < 0.1f && c.y < 0.2f;
            warm += c.x > 0.9f && c.y > 0.3f && c.y < 0.7f && c.z < 0.1f;
        }
    EXPECT_GT(blue, 5);
    EXPECT_GT(warm, 5);
}

} // namespace
} // namespace raylab::ui
