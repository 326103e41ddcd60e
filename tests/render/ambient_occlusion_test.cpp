// The ambient-occlusion view (debug_views.glsl debugAmbientOcclusion): 1 where nothing lies within
// its distance of the first hit, about 1/2 at the foot of a wall (half the cosine-weighted
// hemisphere faces the wall).
#include "render/debug_buffers.h"
#include "render/progressive_render.h"
#include "render/tracer_variants.h"
#include "scene/scene_loader.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <string>

namespace raylab {
namespace {

class AmbientOcclusionTest : public test::GlTest {
protected:
    // A floor (y = 0) seen from 2 units straight above, filling the view; with `wall` it ends at
    // z = -0.5 in a wall 5 units high.
    static Scene scene(bool wall) {
        const std::string back = wall ? "-0.5" : "-5";
        std::string objects = R"({ "type": "mesh", "positions": [-5, 0, )" + back + ",  5, 0, " + back +
                              R"(,  5, 0, 5,  -5, 0, 5], "indices": [0, 1, 2,  0, 2, 3] })";
        if (wall)
            objects +=
                R"(, { "type": "mesh", "positions": [-5, 0, -0.5,  5, 0, -0.5,  5, 5, -0.5,  -5, 5, -0.5], "indices": [0, 1, 2,  0, 2, 3] })";
        return parseScene(R"({ "camera": { "position": [0, 2, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 60 },
                               "render": { "width": 24, "height": 32, "spp": 64, "rpp": 16 },
                               "objects": [)" + objects + "] }",
                          "ao.json");
    }

    static Image ambientOcclusion(const Scene& s) {
        PathTracer tracer(variantOptions(TracerVariant::Views, TracerEntry::Fragment));
        tracer.setScene(s);
        setTracedView(tracer.program(), DebugView::Ao, 0);
        renderProgressively(tracer, s.render);
        return tracer.readImage();
    }

    static double rowMean(const Image& im, int y) {
        double sum = 0.0;
        for (int x = 0; x < im.width; ++x) sum += im.rgb(x, y).x;
        return sum / im.width;
    }
};

TEST_F(AmbientOcclusionTest, APlaneUnderAnOpenSkyIsUnoccluded) {
    const Image im = ambientOcclusion(scene(false));
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) ASSERT_EQ(im.rgb(x, y).x, 1.0f) << x << ", " << y;
}

TEST_F(AmbientOcclusionTest, TheFootOfAWallIsHalfOccluded) {
    const Image im = ambientOcclusion(scene(true));
    // The bottom row sees the floor more than 1 unit (DEBUG_AO_DISTANCE) from the wall, the top row
    // the wall more than 1 unit above the floor: nothing occludes either.
    EXPECT_EQ(rowMean(im, im.height - 1), 1.0);
    EXPECT_EQ(rowMean(im, 0), 1.0);
    double least = 1.0;
    for (int y = 0; y < im.height; ++y) {
        least = std::min(least, rowMean(im, y));
        for (int x = 0; x < im.width; ++x) {
            ASSERT_GE(im.rgb(x, y).x, 0.0f);
            ASSERT_LE(im.rgb(x, y).x, 1.0f);
        }
    }
    EXPECT_NEAR(least, 0.5, 0.1) << "the row at the corner";
}

} // namespace
} // namespace raylab
