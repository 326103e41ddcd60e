// The BVH-level overlay without a window: the levels are the tracer's own BVH nodes, and their
// projected edges end at the projected box corners.
#include "app/bvh_overlay.h"

#include "scene/scene_loader.h"

#include <gtest/gtest.h>

namespace raylab::ui {
namespace {

Scene loadDefault() { return loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json"); }

bool contains(const Box& outer, const Box& inner) {
    return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) && glm::all(glm::greaterThanEqual(outer.hi, inner.hi));
}

TEST(BvhOverlay, DepthZeroIsTheRootAndEveryLevelCoversEveryObject) {
    const Scene s = loadDefault();
    const SceneGeometry g = buildSceneGeometry(s);
    const auto root = bvhLevel(g.topNodes, 0, 0);
    ASSERT_EQ(root.size(), 1u);
    EXPECT_EQ(root[0].lo, glm::vec3(g.topNodes[0].boundsMin));
    EXPECT_EQ(root[0].hi, glm::vec3(g.topNodes[0].boundsMax));
    // The root's children at depth 1: two boxes inside the root.
    const auto one = bvhLevel(g.topNodes, 0, 1);
    ASSERT_EQ(one.size(), 2u);
    for (const Box& b : one) EXPECT_TRUE(contains(root[0], b));
    for (int depth = 0; depth <= g.maxDepth + 1; ++depth) {
        const auto level = bvhLevel(g.topNodes, 0, depth);
        // Each object's box lies inside some box of the level (the level partitions the objects).
        for (const Sphere& sp : s.spheres) {
            const Box ob = objectBounds(sp);
            bool inside = false;
            for (const Box& b : level) inside |= contains(Box{b.lo - 1e-3f, b.hi + 1e-3f}, ob);
            EXPECT_TRUE(inside) << "depth " << depth;
        }
    }
    // Deep enough, the level is the leaves: no fewer boxes than objects / leaf size.
    EXPECT_GE(bvhLevel(g.topNodes, 0, 64).size(), (s.spheres.size() + 3) / 4);
}

TEST(BvhOverlay, ProjectedEdgesEndAtTheProjectedCornersOfTheLevelsBoxes) {
    Scene s = loadDefault();
    s.spheres.erase(s.spheres.begin());   // without the ground, every box is in front of the eye
    const SceneGeometry g = buildSceneGeometry(s);
    const int w = 320, h = 180, depth = 1;
    const auto boxes = bvhLevel(g.topNodes, 0, depth);
    const auto segs = topLevelBvhSegments(s, g, w, h, depth);
    ASSERT_EQ(segs.size(), 12 * boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        const Box& b = boxes[k];
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z);
            const auto p = projectPoint(s, w, h, corner);
            ASSERT_TRUE(p);
            int ends = 0;   // three edges meet at each corner
            for (std::size_t e = 12 * k; e < 12 * (k + 1); ++e)
                for (const ImagePoint q : {segs[e].a, segs[e].b})
                    ends += std::abs(q.x - p->x) < 1e-3f && std::abs(q.y - p->y) < 1e-3f;
            EXPECT_EQ(ends, 3) << "box " << k << " corner " << i;
        }
    }
}

TEST(BvhOverlay, MeshLevelsGoThroughTheObjectsTransform) {
    Scene s;
    s.camera.position = glm::vec3(0.0f, 0.0f, 10.0f);
    s.camera.lookAt = glm::vec3(0.0f);
    s.materials.push_back(Material{});
    Mesh quad;
    quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    quad.transform.translation = glm::vec3(2.0f, 0.0f, 0.0f);
    quad.transform.scale = glm::vec3(0.5f);
    s.meshes.push_back(quad);
    const SceneGeometry g = buildSceneGeometry(s);
    const auto segs = meshBvhSegments(s, g, 640, 360, 0);
    ASSERT_EQ(segs.size(), 12u);
    // The root box of the quad, [-1, 1]² × 0 in object space, lands on [1.5, 2.5] × [-0.5, 0.5].
    const auto lo = projectPoint(s, 640, 360, glm::vec3(1.5f, -0.5f, 0.0f));
    const auto hi = projectPoint(s, 640, 360, glm::vec3(2.5f, 0.5f, 0.0f));
    float minX = 1e9f, maxX = -1e9f, minY = 1e9f, maxY = -1e9f;
    for (const Segment& e : segs)
        for (const ImagePoint q : {e.a, e.b}) {
            minX = std::min(minX, q.x);
            maxX = std::max(maxX, q.x);
            minY = std::min(minY, q.y);
            maxY = std::max(maxY, q.y);
        }
    EXPECT_NEAR(minX, lo->x, 1e-3f);
    EXPECT_NEAR(maxX, hi->x, 1e-3f);
    EXPECT_NEAR(minY, hi->y, 1e-3f);   // image y runs down
    EXPECT_NEAR(maxY, lo->y, 1e-3f);
}

} // namespace
} // namespace raylab::ui
