// Every debug view and the mesh-BVH and selected-object overlays through the real `raylab` window
// under Xvfb (tests/ui/viewer_run.h): one scripted run walks the views the viewer knows
// (ui/app/debug_view.h, so a view added there is walked too), screenshots and exports each, and
// checks what each should show; then the overlays. Skips (with the reason) only where Xvfb is not installed.
#include "accel/scene_geometry.h"
#include "app/bvh_overlay.h"
#include "app/debug_view.h"
#include "app/view_geometry.h"
#include "scene/scene_loader.h"
#include "ui/viewer_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>

namespace raylab::ui {
namespace {

using namespace test_run;

// A scene with a sky (direct / indirect / bounce views), textured meshes with uvs (uv view; the
// mesh-BVH overlay) and spheres (the selected-object overlay).
const std::string kScene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/textured_bricks.json";
constexpr int kSpp = 8;   // the target: tracing stops there, so every screenshot is deterministic
constexpr int kSelected = 0;   // the red sphere
// The mesh-BVH overlay on a mesh with a deep BVH (8192 triangles; the bricks' cube is too
// shallow for levels to differ much), at a level whose inner splits show.
const std::string kTerrain = std::string(RAYLAB_SOURCE_DIR) + "/scenes/displaced_terrain.json";
constexpr int kBvhDepth = 3;

std::string shotName(DebugView v) { return "view-" + std::string(debugViewName(v)); }

class ViewerViewsWindowTest : public ViewerRunSuite<ViewerViewsWindowTest> {
protected:
    static void SetUpTestSuite() {
        if (!startXvfb("raylab_viewer_views_window")) return;
        const std::string d = dir_.string();
        std::string script = "set render.spp " + std::to_string(kSpp) + "\nwait-spp " + std::to_string(kSpp) +
                             "\nscreenshot " + d + "/beauty.png\nexport " + d + "/beauty.exr\n";
        for (DebugView v : kDebugViews) {
            if (v == DebugView::Beauty) continue;
            script += "debug-view " + std::string(debugViewName(v)) + "\nwait-spp " + std::to_string(kSpp) + "\nscreenshot " +
                      d + "/" + shotName(v) + ".png\nexport " + d + "/" + shotName(v) + ".exr\n";
        }
        script += "debug-view beauty\nwait-spp " + std::to_string(kSpp) + "\nscreenshot " + d + "/beauty-again.png\n"
                  "select " + std::to_string(kSelected) + "\noverlay selected on\nscreenshot " + d + "/selected.png\n"
                  "overlay selected off\nopen " + kTerrain + "\nset render.spp 4\nwait-spp 4\nscreenshot " + d + "/terrain.png\n"
                  "bvh-depth " + std::to_string(kBvhDepth) + "\noverlay mesh-bvh on\nscreenshot " + d + "/mesh-bvh.png\nquit\n";
        ViewerOptions small;
        small.scale = 0.25f;   // 120 x 68 traced: the views, not the tracing, are under test
        small.windowWidth = 960;
        small.windowHeight = 600;
        small.scriptTimeout = 400;   // a shader variant per kind of view, compiled on llvmpipe
        run_ = new ViewerRun(runViewer(*xvfb_, dir_, script, kScene, small));
    }
};

// What the run saved of one view, and what the checks compare it with.
struct ViewRun {
    const Shot& beauty;      // window, beauty view
    const Shot& shot;        // window, this view
    const Image& beautyExr;  // traced values (linear), beauty
    const Image& exr;        // traced values of this view (display-only views: the beauty path's)
    const std::vector<bool>& sky;   // traced pixels whose camera rays all miss (depth view 0), away from edges
};

double luminance(glm::vec3 c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

// Checks of the views for which "differs from the beauty image" says too little or is not true.
// Every other view (and one added later) only has to differ clearly from the beauty image.
const std::map<DebugView, std::function<void(const ViewRun&)>>& specialChecks() {
    static const std::map<DebugView, std::function<void(const ViewRun&)>> checks = {
        // A clean scene has no NaN/Inf sample: nothing is flagged magenta, and every pixel is the
        // beauty image's display luminance at 0.35 in grey (shaders/entry/display.frag). "Differs"
        // would pass for any view, even one that flags everything.
        {DebugView::NonFinite,
         [](const ViewRun& r) {
             int magenta = 0, off = 0, n = 0;
             for (int y = int(r.shot.y) + 1; y < int(r.shot.y + r.shot.h) - 1; ++y)
                 for (int x = int(r.shot.x) + 1; x < int(r.shot.x + r.shot.w) - 1; ++x, ++n) {
                     const glm::vec3 c = r.shot.image.rgb(x, y);
                     magenta += c.x > 0.9f && c.y < 0.1f && c.z > 0.9f;
                     const double grey = 0.35 * luminance(r.beauty.image.rgb(x, y));
                     // 8-bit rounding of both images (the beauty shot's luminance is of rounded values).
                     off += std::abs(double(c.x) - grey) > 1.5 / 255.0 || c.x != c.y || c.y != c.z;
                 }
             EXPECT_EQ(magenta, 0);
             EXPECT_EQ(off, 0) << "of " << n << " pixels not grey at 0.35 x the beauty luminance";
         }},
        // Light after exactly one bounce: the sky seen directly is bounce 0, so the sky is black.
        {DebugView::BounceK,
         [](const ViewRun& r) {
             int lit = 0, litSky = 0;
             for (int y = 0; y < r.exr.height; ++y)
                 for (int x = 0; x < r.exr.width; ++x) {
                     if (r.sky[std::size_t(y * r.exr.width + x)]) litSky += r.exr.rgb(x, y) != glm::vec3(0.0f);
                     else lit += luminance(r.exr.rgb(x, y)) > 0.0;
                 }
             EXPECT_EQ(litSky, 0);
             EXPECT_GT(lit, r.exr.width * r.exr.height / 3) << "directly lit surfaces";
         }},
        // Bounces 0 and 1: the sky seen directly is the beauty image's; surfaces lack their
        // indirect light: none is brighter than in the beauty image, and the whole is darker. In
        // an open-sky scene nearly all light is direct, so the view looks much like the beauty
        // image (mean window difference 0.008): "differs" would say nothing.
        {DebugView::Direct,
         [](const ViewRun& r) {
             double direct = 0.0, beauty = 0.0;
             int skyDiffers = 0, brighter = 0;
             for (int y = 0; y < r.exr.height; ++y)
                 for (int x = 0; x < r.exr.width; ++x) {
                     const glm::vec3 d = r.exr.rgb(x, y), b = r.beautyExr.rgb(x, y);
                     if (r.sky[std::size_t(y * r.exr.width + x)]) {
                         skyDiffers += glm::length(d - b) > 1e-5f * glm::length(b);
                     } else {
                         direct += luminance(d);
                         beauty += luminance(b);
                         // The same paths (same seed) with terms left out: float rounding only.
                         brighter += glm::any(glm::greaterThan(d, b * (1.0f + 1e-5f)));
                     }
                 }
             EXPECT_EQ(skyDiffers, 0);
             EXPECT_EQ(brighter, 0);
             EXPECT_LT(direct, beauty);
             std::printf("direct light: %.1f%% of the surfaces' luminance\n", 100.0 * direct / beauty);
         }},
        // Bounces 2 and more: none for the sky seen directly; surfaces that see other surfaces
        // (the floor round the cube and the spheres, the objects' lower halves) receive some.
        {DebugView::Indirect,
         [](const ViewRun& r) {
             int lit = 0, litSky = 0, surface = 0;
             for (int y = 0; y < r.exr.height; ++y)
                 for (int x = 0; x < r.exr.width; ++x) {
                     if (r.sky[std::size_t(y * r.exr.width + x)]) {
                         litSky += r.exr.rgb(x, y) != glm::vec3(0.0f);
                     } else {
                         ++surface;
                         lit += luminance(r.exr.rgb(x, y)) > 0.0;
                     }
                 }
             EXPECT_EQ(litSky, 0);
             std::printf("indirect light on %d of %d surface pixels\n", lit, surface);
             EXPECT_GT(lit, surface / 10);
         }},
        // fract(uv) in red and green, 0 in blue and for the sky; the floor repeats its uvs 20
        // times, so both cover most of [0, 1).
        {DebugView::Uv,
         [](const ViewRun& r) {
             float uMin = 1.0f, uMax = 0.0f, vMin = 1.0f, vMax = 0.0f;
             int outOfRange = 0, litSky = 0;
             for (int y = 0; y < r.exr.height; ++y)
                 for (int x = 0; x < r.exr.width; ++x) {
                     const glm::vec3 c = r.exr.rgb(x, y);
                     outOfRange += c.z != 0.0f || c.x < 0.0f || c.x >= 1.0f || c.y < 0.0f || c.y >= 1.0f;
                     if (r.sky[std::size_t(y * r.exr.width + x)]) {
                         litSky += c != glm::vec3(0.0f);
                         continue;
                     }
                     uMin = std::min(uMin, c.x), uMax = std::max(uMax, c.x);
                     vMin = std::min(vMin, c.y), vMax = std::max(vMax, c.y);
                 }
             EXPECT_EQ(outOfRange, 0);
             EXPECT_EQ(litSky, 0);
             EXPECT_GT(uMax - uMin, 0.8f);
             EXPECT_GT(vMax - vMin, 0.8f);
         }},
        // Relative error of the mean: the sky barely varies within a pixel, so it shows the
        // ramp's blue end (error ~0); the diffuse surfaces at 8 spp do not.
        {DebugView::Noise,
         [](const ViewRun& r) {
             const float sx = r.shot.w / float(r.exr.width), sy = r.shot.h / float(r.exr.height);
             int sky = 0, blue = 0;
             for (int y = 0; y < r.exr.height; ++y)
                 for (int x = 0; x < r.exr.width; ++x) {
                     if (!r.sky[std::size_t(y * r.exr.width + x)]) continue;
                     const glm::vec3 c = r.shot.image.rgb(int(r.shot.x + (float(x) + 0.5f) * sx), int(r.shot.y + (float(y) + 0.5f) * sy));
                     ++sky;
                     blue += c.z > 0.8f && c.x < 0.1f;
                 }
             ASSERT_GT(sky, 100);
             EXPECT_EQ(blue, sky);
         }},
    };
    return checks;
}

TEST_F(ViewerViewsWindowTest, EveryDebugViewAndOverlay) {
    const Image beautyExr = readImage(dir_ / "beauty.exr");
    const Image depth = readImage(dir_ / (shotName(DebugView::Depth) + ".exr"));
    const int w = beautyExr.width, h = beautyExr.height;
    ASSERT_EQ(w, 120);
    ASSERT_EQ(depth.width, w);
    // Sky pixels: the depth view is 0 where every camera ray missed; a pixel counts when its
    // neighbours did too (pixel jitter differs in nothing, but edges are where doubt would be).
    std::vector<bool> sky(std::size_t(w * h), false);
    int skyCount = 0;
    for (int y = 1; y < h - 1; ++y)
        for (int x = 1; x < w - 1; ++x) {
            bool all = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) all = all && depth.rgb(x + dx, y + dy).x == 0.0f;
            sky[std::size_t(y * w + x)] = all;
            skyCount += all;
        }
    ASSERT_GT(skyCount, w * h / 10) << "the view shows sky";

    const Shot& beauty = shot("beauty");
    for (DebugView v : kDebugViews) {
        if (v == DebugView::Beauty) continue;
        SCOPED_TRACE(std::string(debugViewName(v)));
        const Shot& s = shot(shotName(v));
        const Image exr = readImage(dir_ / (shotName(v) + ".exr"));
        ASSERT_EQ(exr.width, w);
        const double d = imageDifference(beauty, s);
        std::printf("%-12s mean |view - beauty| over the image %.4f\n", std::string(debugViewName(v)).c_str(), d);
        const auto special = specialChecks().find(v);
        if (special != specialChecks().end()) special->second(ViewRun{beauty, s, beautyExr, exr, sky});
        if (v != DebugView::NonFinite && v != DebugView::Direct) {   // their checks above say more
            EXPECT_GT(d, 0.02) << "the view looks like the beauty image";
        }
    }
    {
        SCOPED_TRACE("back to beauty: the same samples, the same image");
        EXPECT_EQ(imageDifference(beauty, shot("beauty-again")), 0.0);
    }
    const Scene scene = loadScene(kScene);
    {
        SCOPED_TRACE("mesh BVH overlay pixels land on the projected boxes of its level");
        const Scene terrain = loadScene(kTerrain);
        ASSERT_EQ(terrain.render.width, scene.render.width);   // the same traced size, w x h
        ASSERT_EQ(terrain.render.height, scene.render.height);
        const SceneGeometry g = buildSceneGeometry(terrain);
        const Shot& off = shot("terrain");
        const Shot& on = shot("mesh-bvh");
        const auto [changed, far] = overlayPixels(off, on, toWindow(on, meshBvhSegments(terrain, g, w, h, kBvhDepth), w, h));
        std::printf("mesh BVH overlay: %d pixels changed, %d off the boxes of level %d\n", changed, far, kBvhDepth);
        EXPECT_GT(changed, 500) << "no overlay drawn";
        EXPECT_EQ(far, 0) << "of " << changed << " overlay pixels";
        // The check tells levels apart: the level above leaves the inner splits unexplained.
        const OverlayPixels above = overlayPixels(off, on, toWindow(on, meshBvhSegments(terrain, g, w, h, kBvhDepth - 1), w, h));
        std::printf("  %d off the boxes of level %d\n", above.far, kBvhDepth - 1);
        EXPECT_GT(above.far, changed / 20);
    }
    {
        SCOPED_TRACE("the selected overlay draws the selected sphere's box only");
        const Shot& on = shot("selected");
        const auto box = projectBox(scene, w, h, objectBounds(scene.spheres[std::size_t(kSelected)]));
        const auto [changed, far] = overlayPixels(shot("beauty-again"), on, toWindow(on, box, w, h));
        std::printf("selected overlay: %d pixels changed, %d off the box\n", changed, far);
        EXPECT_GT(changed, 100) << "no overlay drawn";
        EXPECT_EQ(far, 0) << "of " << changed << " overlay pixels";
    }
}

} // namespace
} // namespace raylab::ui
