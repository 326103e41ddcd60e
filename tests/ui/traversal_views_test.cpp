// The viewer's heat maps (box and triangle tests per camera ray), its uv view, click-to-focus and
// the scene statistics, on a headless context: every pixel's value is checked against the tracer's
// traversal run on the CPU for the very same ray (same sampler stream, same jitter).
#include "app/viewer.h"

#include "accel/cpu_traversal.h"
#include "inspect/sample_points.h"
#include "render/camera_relative.h"
#include "render/render_helpers.h"
#include "render/scene_stats.h"
#include "shaders/include/camera.glsl"
#include "shaders/include/random.glsl"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace raylab::ui {
namespace {

// 20 spheres (more than kLinearTopLevelMax, so the tracer traverses the top-level BVH) in front of
// a textured wall whose uvs repeat three times; sky above the wall.
Scene spheresBeforeAWall() {
    Scene s;
    s.camera.position = glm::vec3(0.0f, 2.0f, 12.0f);
    s.camera.lookAt = glm::vec3(0.0f, 1.0f, 0.0f);
    s.camera.fovY = 40.0f;
    s.render.width = 48;
    s.render.height = 27;
    s.render.spp = 1;
    s.render.seed = 7;
    Material plain;
    plain.name = "plain";
    Material textured;
    textured.name = "textured";
    textured.albedoTextureIndex = 0;
    textured.albedoTexture = "generated";
    s.materials = {plain, textured};
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 4; ++j) s.spheres.push_back(Sphere{glm::vec3(-4.0f + 2.0f * float(i), 0.5f, -2.0f + 2.0f * float(j)), 0.4f, 0, {}});
    Mesh wall;
    wall.positions = {{-6, 0, -4}, {6, 0, -4}, {6, 4, -4}, {-6, 4, -4}};
    wall.uvs = {{0, 0}, {3, 0}, {3, 1.5f}, {0, 1.5f}};
    wall.triangles = {{0, 1, 2}, {0, 2, 3}};
    wall.material = 1;
    s.meshes.push_back(wall);
    MipLevel base;
    base.width = 2;
    base.height = 2;
    base.texels = {glm::vec4(1.0f), glm::vec4(0.5f), glm::vec4(0.5f), glm::vec4(1.0f)};
    Texture t;
    t.file = "srgb:generated";
    t.levels = buildMipPyramid(base);
    s.textures.push_back(t);
    return s;
}

struct CpuSample {
    bool hit = false;
    glsl::TraceRecord rec;
    glsl::Ray ray;
    std::uint64_t boxes = 0;
    std::uint64_t triangles = 0;
};

// The camera ray of sample 0 of image pixel (x, y) (top row 0), exactly as path_tracer.glsl makes
// it, traced by the CPU copy of the tracer's traversal.
CpuSample cpuSample(const Scene& s, const SceneGeometry& g, int x, int y) {
    const int w = s.render.width, h = s.render.height;
    const glm::uvec2 pixel(unsigned(x), unsigned(h - 1 - y));   // GL rows start at the bottom
    SamplePointsQuery jitter;   // the scene's sampler, as the tracer draws it (inspect/sample_points.h)
    jitter.sampler = s.render.sampler;
    jitter.pixel = pixel;
    jitter.seed = s.render.seed;
    jitter.spp = std::uint32_t(std::max(s.render.spp, 1));
    jitter.count = 1;
    const glm::vec2 ndc = (glm::vec2(pixel) + samplePoints(jitter)[0]) / glm::vec2(float(w), float(h)) * 2.0f - 1.0f;
    const auto cam = glsl::cameraBasis(s.camera.position, s.camera.lookAt, s.camera.up, s.camera.fovY, float(w) / float(h));
    CpuSample out;
    out.ray = glsl::cameraRay(cam, ndc);
    glsl::cpuTraversal = {&g, 0, 0};
    out.hit = glsl::traceScene(out.ray, glsl::FLOAT_MAX, false, out.rec);
    out.boxes = glsl::cpuTraversal.boxTests;
    out.triangles = glsl::cpuTraversal.triangleTests;
    glsl::cpuTraversal.geometry = nullptr;
    return out;
}

class TraversalViewsTest : public test::GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        viewer = std::make_unique<Viewer>(log);
        ASSERT_TRUE(viewer->openScene(test::scenePath("default.json"))) << viewer->document().lastError();
        viewer->scene() = spheresBeforeAWall();
        viewer->document().changed(Trigger::ReloadScene);
        ASSERT_TRUE(viewer->hasScene());
    }
    Image trace(DebugView v) {
        viewer->setDebugView(v);
        for (int i = 0; i < 1000 && !viewer->converged(); ++i) viewer->update(1e-5);
        EXPECT_TRUE(viewer->converged());
        return viewer->tracer()->readImage();
    }
    Log log{false};
    std::unique_ptr<Viewer> viewer;
};

TEST_F(TraversalViewsTest, HeatMapsCountTheTestsOfTheCpuTraversalForTheSameRay) {
    const Image beauty = trace(DebugView::Beauty);
    const Image heat = trace(DebugView::Boxes);
    EXPECT_EQ(viewer->debugView(), DebugView::Boxes);
    EXPECT_GT(test::rmse(beauty, heat), 1.0) << "the view is counts, not radiance";
    const Scene& s = viewer->scene();
    const SceneGeometry& g = *viewer->geometry();
    ASSERT_GT(g.topNodes.size(), 1u);
    ASSERT_FALSE(viewer->tracer()->features().linearTopLevel);
    // The GPU traverses the top level built over the camera-relative scene (render/gpu_scene.cpp,
    // render/camera_relative.h): mirror that one.
    const Scene relative = cameraRelative(s, viewer->tracer()->origin());
    SceneGeometry uploaded = g;
    updateTopLevel(uploaded, relative);
    int mismatches = 0;
    std::uint64_t boxSum = 0, triangleSum = 0, boxMax = 0;
    for (int y = 0; y < s.render.height; ++y)
        for (int x = 0; x < s.render.width; ++x) {
            const CpuSample c = cpuSample(relative, uploaded, x, y);
            const glm::vec3 v = heat.rgb(x, y);
            if (v.x != float(c.boxes) || v.y != float(c.triangles)) {
                if (++mismatches <= 5)
                    ADD_FAILURE() << "pixel (" << x << ", " << y << "): GPU " << v.x << " boxes, " << v.y
                                  << " triangles; CPU " << c.boxes << ", " << c.triangles;
            }
            EXPECT_EQ(v.z, 0.0f);
            boxSum += c.boxes;
            triangleSum += c.triangles;
            boxMax = std::max(boxMax, c.boxes);
        }
    EXPECT_EQ(mismatches, 0);
    // The per-pixel counts are the tracer's counters: they add up to its totals for the pass, and
    // the automatic scale is the largest count of one ray.
    EXPECT_EQ(viewer->tracer()->boxTests(), boxSum);
    EXPECT_EQ(viewer->tracer()->triangleTests(), triangleSum);
    EXPECT_FLOAT_EQ(viewer->heatScaleInUse(), float(boxMax));
    EXPECT_GT(triangleSum, 0u);
    // The top row looks at the sky above the wall: the ray tests boxes but no triangle.
    for (int x = 0; x < s.render.width; ++x) {
        ASSERT_FALSE(cpuSample(s, g, x, 0).hit);
        EXPECT_EQ(heat.rgb(x, 0).y, 0.0f);
        EXPECT_GE(heat.rgb(x, 0).x, 1.0f);   // at least the root box
    }
    // Boxes and triangles are two channels of the same samples: switching only redraws.
    viewer->setDebugView(DebugView::Triangles);
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 1u);
    EXPECT_EQ(viewer->tracer()->readImage().rgba, heat.rgba);
    viewer->heatScaleAuto = false;
    viewer->heatScale = 5.0f;
    EXPECT_FLOAT_EQ(viewer->heatScaleInUse(), 5.0f);
    EXPECT_NE(viewer->displayTexture(), 0u);
}

TEST_F(TraversalViewsTest, TheUvViewShowsTheInterpolatedUvsFractionalPart) {
    const Image uv = trace(DebugView::Uv);
    const Scene& s = viewer->scene();
    const SceneGeometry& g = *viewer->geometry();
    int wallPixels = 0, wrapped = 0;
    for (int y = 0; y < s.render.height; ++y)
        for (int x = 0; x < s.render.width; ++x) {
            const CpuSample c = cpuSample(s, g, x, y);
            const glm::vec3 v = uv.rgb(x, y);
            if (!c.hit) {
                EXPECT_EQ(v, glm::vec3(0.0f));
                continue;
            }
            if (g.instances[c.rec.instance].info.x != glsl::INSTANCE_MESH) continue;
            glsl::cpuTraversal.geometry = &g;
            const glsl::SurfaceHit sh = glsl::surfaceAt(c.ray, c.rec);
            glsl::cpuTraversal.geometry = nullptr;
            const glm::vec2 expected = glm::fract(sh.uv);
            ++wallPixels;
            wrapped += sh.uv.x >= 1.0f;
            EXPECT_NEAR(v.x, expected.x, 1e-4f) << x << ", " << y;
            EXPECT_NEAR(v.y, expected.y, 1e-4f) << x << ", " << y;
            EXPECT_EQ(v.z, 0.0f);
        }
    EXPECT_GT(wallPixels, 100);
    EXPECT_GT(wrapped, 10) << "some pixels see u beyond 1: the view shows its fractional part";
}

TEST_F(TraversalViewsTest, ClickToFocusSetsTheFocusDistanceKey) {
    // The depth itself is checked against analytic values in focus_pick_test.cpp; here the key
    // changes, accumulation restarts, and a click on the sky leaves the key alone.
    trace(DebugView::Beauty);
    const auto d = viewer->focusAt(24.0f, 8.0f);   // the wall, 16 units ahead
    ASSERT_TRUE(d);
    EXPECT_GT(*d, 14.0f);
    EXPECT_LT(*d, 16.0f) << "depth along the (tilted) view axis, less than the distance along z";
    EXPECT_FLOAT_EQ(viewer->scene().camera.focusDistance, *d);
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 0u);
    EXPECT_FALSE(viewer->focusAt(24.0f, 0.5f));
    EXPECT_FLOAT_EQ(viewer->scene().camera.focusDistance, *d);
}

TEST_F(TraversalViewsTest, StatisticsOfTheSceneOnTheGpu) {
    const SceneStats st = sceneStats(viewer->scene(), *viewer->geometry());
    EXPECT_EQ(st.objects, 21u);
    EXPECT_EQ(st.triangles, 2u);
    EXPECT_EQ(st.textures, 1u);
    EXPECT_EQ(st.textureBytes, (4u + 1u) * 16u + (1u + 2u + 1u) * 16u);   // 2x2 and 1x1 levels, the table
}

} // namespace
} // namespace raylab::ui
