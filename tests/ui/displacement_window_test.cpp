// Live displacement edits in the real `raylab` window under Xvfb: on scenes/displaced_quad.json,
// the script's `set selected.displacement_scale` and `displacement_subdivision` tessellate and
// displace the mesh again (the image changes, the log reports the new triangle count), and a bad
// value is a located error in the log while the scene keeps rendering. Skips (with the reason)
// only where Xvfb is not installed.
#include "io/image_io.h"
#include "ui/viewer_run.h"
#include "ui/xvfb.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab::ui {
namespace {

using namespace test_run;

// Mean absolute difference per channel value of two images of one size.
double meanDifference(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) sum += std::abs(double(a.rgba[i]) - double(b.rgba[i]));
    return sum / double(a.rgba.size());
}

TEST(DisplacementWindow, EditsRetessellateLiveAndABadValueKeepsTheScene) {
    RAYLAB_START_XVFB(x);
    const fs::path dir = test::windowTestDir("raylab_displacement_window_");
    const std::string d = dir.string(), scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/displaced_quad.json";
    const ViewerRun run = runViewer(x, dir,
                                    "wait-spp 4\npause\nexport " + d + "/loaded.exr\n"
                                    "resume\nwait-spp 8\npause\nexport " + d + "/more.exr\n"
                                    "select 0\nset selected.displacement_scale 0.5\nresume\nwait-spp 4\npause\n"
                                    "export " + d + "/higher.exr\n"
                                    "set selected.displacement_subdivision 3\n"
                                    "set selected.displacement_subdivision 9\n"
                                    "set objects.0.displacement_texture textures/missing.ppm\n"
                                    "resume\nwait-spp 4\npause\nexport " + d + "/kept.exr\nquit\n",
                                    scene);
    EXPECT_EQ(run.status, 1) << "the two bad sets fail the script\n" << run.log;
    EXPECT_NE(run.log.find("objects.0.displacement_scale: displaced again: 2 -> 32768 triangles in "), std::string::npos)
        << run.log;
    EXPECT_NE(run.log.find("objects.0.displacement_subdivision: displaced again: 2 -> 128 triangles in "), std::string::npos)
        << run.log;
    EXPECT_NE(run.log.find("objects.0.displacement_subdivision: must be in [0, 8], got 9"), std::string::npos) << run.log;
    EXPECT_NE(run.log.find("objects[0].displacement_texture: " + std::string(RAYLAB_SOURCE_DIR) +
                           "/scenes/textures/missing.ppm: cannot read: no such file"),
              std::string::npos)
        << run.log;
    const Image loaded = readImage(dir / "loaded.exr"), more = readImage(dir / "more.exr"),
                higher = readImage(dir / "higher.exr"), kept = readImage(dir / "kept.exr");
    ASSERT_EQ(loaded.rgba.size(), higher.rgba.size());
    ASSERT_EQ(loaded.rgba.size(), more.rgba.size());
    ASSERT_EQ(higher.rgba.size(), kept.rgba.size());
    // Bricks 0.5 high instead of 0.03 stand far out of the tile: the picture changes far more than
    // the noise between 4 and 8 samples of one scene does.
    EXPECT_GT(meanDifference(loaded, higher), 3.0 * meanDifference(loaded, more)) << "the scale edit changes the image";
    // The bad values leave the scene at subdivision 3 (coarser bricks than `higher`), still rendering.
    double keptSum = 0.0;
    for (float v : kept.rgba) keptSum += v;
    EXPECT_GT(keptSum / double(kept.rgba.size()), 0.02) << "the scene still renders after the bad values";
    EXPECT_GT(meanDifference(higher, kept), 0.0) << "subdivision 3 is another surface";
    std::error_code ec;
    fs::remove_all(dir, ec);
}

} // namespace
} // namespace raylab::ui
