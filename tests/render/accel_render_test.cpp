// render.accel on the GPU (OSMesa): boxes and none find the BVH's hits, so they render its image
// bit for bit, on the Cornell box and on a textured mesh scene; the traversal counters (heat views,
// stats) count their work: more triangles than the BVH, every object's box for boxes.
#include "render_helpers.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

using namespace raylab;

namespace {

struct Traced {
    Image image;
    std::uint64_t boxes = 0;
    std::uint64_t triangles = 0;
    std::uint64_t rays = 0;
};

Traced trace(const std::string& scene, const std::string& accel) {
    TracerOptions counting;
    counting.extraDefines = {{"RAYLAB_COUNT_TRAVERSAL", "1"}};
    const Scene s = loadScene(test::scenePath(scene), {"render.width=24", "render.height=16", "render.spp=2",
                                                       "render.rpp=2", "render.accel=" + accel});
    PathTracer tracer(counting);
    tracer.setScene(s);
    renderProgressively(tracer, s.render);
    return {tracer.readImage(), tracer.boxTests(), tracer.triangleTests(), tracer.raysTraced()};
}

} // namespace

class AccelRenderTest : public test::GlTest {};

TEST_F(AccelRenderTest, BoxesAndNoneRenderTheBvhsImageAtAHigherCost) {
    for (const char* scene : {"cornell_box.json", "textured_bricks.json"}) {
        SCOPED_TRACE(scene);
        const Traced bvh = trace(scene, "bvh");
        const Traced boxes = trace(scene, "boxes");
        const Traced none = trace(scene, "none");
        EXPECT_EQ(boxes.image.rgba, bvh.image.rgba) << "same hits, same image";
        EXPECT_EQ(none.image.rgba, bvh.image.rgba) << "same hits, same image";
        EXPECT_EQ(boxes.rays, bvh.rays);
        EXPECT_GT(bvh.triangles, 0u);
        EXPECT_GT(boxes.triangles, bvh.triangles);
        EXPECT_GT(none.triangles, boxes.triangles);
        EXPECT_GT(boxes.boxes, 0u);
        EXPECT_EQ(none.boxes, 0u) << "none tests no box";
    }
}
