#include "app/view_geometry.h"

#include "scene/scene_loader.h"
#include "shaders/include/camera.glsl"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab::ui {
namespace {

Scene defaultScene() { return loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json"); }

TEST(ViewGeometry, ProjectionInvertsTheTracersCameraRay) {
    const Scene s = defaultScene();
    const int w = 640, h = 360;
    const auto b = glsl::cameraBasis(s.camera.position, s.camera.lookAt, s.camera.up, s.camera.fovY, float(w) / float(h));
    for (const ImagePoint p : {ImagePoint{10.5f, 20.5f}, ImagePoint{320.0f, 180.0f}, ImagePoint{600.25f, 350.75f}}) {
        const glm::vec2 ndc(p.x / float(w) * 2.0f - 1.0f, 1.0f - p.y / float(h) * 2.0f);
        const glsl::Ray r = glsl::cameraRay(b, ndc);
        const auto q = projectPoint(s, w, h, r.origin + 7.0f * r.dir);
        ASSERT_TRUE(q);
        EXPECT_NEAR(q->x, p.x, 1e-3f);
        EXPECT_NEAR(q->y, p.y, 1e-3f);
    }
}

TEST(ViewGeometry, ClickingASpheresProjectedCentrePicksIt) {
    const Scene s = defaultScene();
    for (int i = 1; i < int(s.spheres.size()); ++i) {   // 0 is the ground
        const auto c = projectPoint(s, 640, 360, s.spheres[std::size_t(i)].center);
        ASSERT_TRUE(c);
        EXPECT_EQ(pickObject(s, 640, 360, *c), i);
    }
    EXPECT_FALSE(pickObject(s, 640, 360, ImagePoint{320.0f, 2.0f}));   // the sky
    EXPECT_EQ(pickObject(s, 640, 360, ImagePoint{320.0f, 355.0f}), 0);
}

TEST(ViewGeometry, BoxEdgesEncloseTheSphereSilhouette) {
    const Scene s = defaultScene();
    const Sphere& sp = s.spheres[1];
    const auto segs = projectBox(s, 640, 360, objectBounds(sp));
    ASSERT_EQ(segs.size(), 12u);
    float lo = 1e9f, hi = -1e9f;
    for (const Segment& g : segs) {
        lo = std::min({lo, g.a.x, g.b.x});
        hi = std::max({hi, g.a.x, g.b.x});
    }
    // Points of the sphere's silhouette row project inside the box's horizontal extent.
    const auto c = projectPoint(s, 640, 360, sp.center);
    ASSERT_TRUE(c);
    for (float x = lo - 20.0f; x <= hi + 20.0f; x += 1.0f) {
        const auto hit = pickObject(s, 640, 360, ImagePoint{x, c->y});
        if (hit == 1) {
            EXPECT_GE(x, lo);
            EXPECT_LE(x, hi);
        }
    }
}

TEST(ViewGeometry, EdgesBehindTheEyeAreCut) {
    const Scene s = defaultScene();
    const Box aroundEye{s.camera.position - glm::vec3(1.0f), s.camera.position + glm::vec3(1.0f)};
    const auto segs = projectBox(s, 640, 360, aroundEye);
    EXPECT_GT(segs.size(), 0u);
    EXPECT_LT(segs.size(), 12u);
    for (const Segment& g : segs)
        for (float v : {g.a.x, g.a.y, g.b.x, g.b.y}) EXPECT_TRUE(std::isfinite(v));
}

} // namespace
} // namespace raylab::ui
