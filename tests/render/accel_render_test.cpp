// render.accel on the GPU (OSMesa): boxes and none find the BVH's hits, so they render its image
// bit for bit, on the Cornell box and on a textured mesh scene; the traversal counters (heat views,
// stats) count their work: more triangles than the BVH, every object's box for boxes. A flat
// search of a large mesh stays within llvmpipe's loop budget, so its paths are not cut short.
// Small meshes searched without their BVH render the BVH's image too.
#include "render/shader_variant.h"
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
    std::uint64_t loopLimited = 0;
    int samplesPerDraw = 0;
};

Traced trace(const Scene& s) {
    TracerOptions counting;
    counting.extraDefines = {{"RAYLAB_COUNT_TRAVERSAL", "1"}};
    PathTracer tracer(counting);
    tracer.setScene(s);
    renderProgressively(tracer, s.render);
    return {tracer.readImage(), tracer.boxTests(),           tracer.triangleTests(),
            tracer.raysTraced(), tracer.loopLimitedInvocations(), tracer.samplesPerDraw()};
}

Scene small(const std::string& scene, const std::string& accel = "bvh", int spp = 2, int rpp = 2) {
    return loadScene(test::scenePath(scene), {"render.width=24", "render.height=16", "render.spp=" + std::to_string(spp),
                                              "render.rpp=" + std::to_string(rpp), "render.accel=" + accel});
}

Traced trace(const std::string& scene, const std::string& accel, int spp = 2, int rpp = 2) {
    return trace(small(scene, accel, spp, rpp));
}

bool has(const std::string& variant, const char* name) { return variant.find(name) != std::string::npos; }

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

// Few objects and small meshes (RAYLAB_SMALL_MESHES): the tracer tests a mesh's triangles straight
// after its world box, while the counting variant of the heat views walks the mesh's BVH. Same
// hits, so the same image bit for bit. Both scenes take RAYLAB_MESHES_IN_WORLD (one object
// ray for all meshes): the Cornell box's meshes share a transform, the textured scene's cube's own
// is baked into its vertices (render/baked_mesh_transforms.h); the next test moves a Cornell box mesh.
TEST_F(AccelRenderTest, SmallMeshesSearchedWithoutTheirBvhRenderTheBvhsImage) {
    for (const char* scene : {"cornell_box.json", "textured_bricks.json"}) {
        SCOPED_TRACE(scene);
        const Scene s = loadScene(test::scenePath(scene), {"render.width=24", "render.height=16", "render.spp=2", "render.rpp=2"});
        ASSERT_TRUE(sceneFeatures(s).smallMeshes && sceneFeatures(s).linearTopLevel);
        PathTracer plain;
        plain.setScene(s);
        renderProgressively(plain, s.render);
        EXPECT_NE(plain.variantName().find("small-meshes"), std::string::npos) << plain.variantName();
        EXPECT_TRUE(has(plain.variantName(), "meshes-in-world")) << plain.variantName();
        const Traced bvh = trace(scene, "bvh");
        EXPECT_GT(bvh.boxes, bvh.triangles) << "the counting variant walks the meshes' BVHs";
        EXPECT_EQ(plain.readImage().rgba, bvh.image.rgba) << "same hits, same image";
    }
}

// A Cornell box block moved (and turned) by its own transform: baked into its vertices, so the
// meshes still share the identity; the image is still the BVH's, bit for bit. The viewer moves
// objects through updateTransforms, which bakes the moved block's few triangles again and keeps
// the variant.
TEST_F(AccelRenderTest, MeshesWithTheirOwnTransformsRenderTheBvhsImageAndTheVariantFollowsAMove) {
    const Scene shared = small("cornell_box.json");
    Scene moved = shared;
    Transform& t = moved.meshes.back().transform;
    t.translation = glm::vec3(-20.0f, 0.0f, 15.0f);
    t.rotation = glm::vec3(0.0f, 7.0f, 0.0f);
    ASSERT_TRUE(sceneFeatures(moved).smallMeshes);
    ASSERT_TRUE(sceneFeatures(moved).meshesInWorld);
    ASSERT_TRUE(sceneFeatures(shared).meshesInWorld);

    PathTracer own;
    own.setScene(moved);
    renderProgressively(own, moved.render);
    EXPECT_TRUE(has(own.variantName(), "small-meshes")) << own.variantName();
    EXPECT_TRUE(has(own.variantName(), "meshes-in-world")) << own.variantName();
    const Image ownImage = own.readImage();
    EXPECT_EQ(ownImage.rgba, trace(moved).image.rgba) << "same hits, same image";

    PathTracer tracer;
    tracer.setScene(shared);
    renderProgressively(tracer, shared.render);
    const Image sharedImage = tracer.readImage();
    EXPECT_NE(sharedImage.rgba, ownImage.rgba) << "the block moved in view";
    tracer.updateTransforms(moved);
    EXPECT_TRUE(has(tracer.variantName(), "meshes-in-world")) << tracer.variantName();
    renderProgressively(tracer, moved.render);
    EXPECT_EQ(tracer.readImage().rgba, ownImage.rgba) << "moved by the viewer as loaded moved";
    tracer.updateTransforms(shared);
    EXPECT_TRUE(has(tracer.variantName(), "meshes-in-world")) << tracer.variantName();
    renderProgressively(tracer, shared.render);
    EXPECT_EQ(tracer.readImage().rgba, sharedImage.rgba) << "and back";
}

// The terrain's 8192 triangles in one mesh: one triangle per loop iteration, a few rays spent
// llvmpipe's 65535 iterations and the paths lost light (not bit-equal, 7 % of pixels at 2 spp).
// Passes of 4 samples: the flat search draws 4 at a time here, and a pass drawn in other slices
// sums its samples in another order (equal to the last bit only).
TEST_F(AccelRenderTest, AFlatSearchOfALargeMeshLosesNoPathToTheLoopLimit) {
    const Traced bvh = trace("displaced_terrain.json", "bvh", 16, 4);
    const Traced none = trace("displaced_terrain.json", "none", 16, 4);
    EXPECT_EQ(none.loopLimited, 0u) << "draws cut short by the driver";
    EXPECT_EQ(bvh.loopLimited, 0u);
    EXPECT_EQ(none.image.rgba, bvh.image.rgba) << "same hits, same image";
    EXPECT_GT(none.triangles, 100 * bvh.triangles);
    EXPECT_EQ(bvh.samplesPerDraw, PathTracer::kSamplesPerDraw);
    EXPECT_EQ(none.samplesPerDraw, 4) << "a flat search draws fewer samples at once (below)";
}

// Two spheres and the terrain (8192 triangles, max_bounces 6): in whole steps per ray 2 + (1 + 8192 /
// 16) iterations, 2 · 7 rays per sample; 32767 of them leave 4 samples per draw. One triangle per
// iteration, a sample would need 14 · 8195, more than the budget: the terrain takes the steps. A
// Cornell box wall (2 triangles) costs 1 + 2, a block (10) 1 + 10 either way: no steps there.
TEST(FlatLoopIterations, CountsEveryObjectAndEachStepOfItsTriangles) {
    Scene s = loadScene(test::scenePath("displaced_terrain.json"));
    EXPECT_EQ(flatLoopIterationsPerSample(s, true), 0u) << "the BVH";
    EXPECT_FALSE(sceneFeatures(s).usesFlatSteps());
    s.render.accel = Accel::None;
    EXPECT_EQ(flatLoopIterationsPerSample(s, true), 515u * 14u);
    EXPECT_EQ(flatLoopIterationsPerSample(s, false), 8195u * 14u);
    EXPECT_TRUE(sceneFeatures(s).flatSteps);
    EXPECT_NE(featureName(sceneFeatures(s)).find("flat-steps"), std::string::npos);
    s.render.accel = Accel::Boxes;
    s.render.maxBounces = 0;
    s.ao.rays = 1;
    EXPECT_EQ(flatLoopIterationsPerSample(s, true), 515u * 2u);
    s.ao.rays = 64;
    EXPECT_EQ(flatLoopIterationsPerSample(s, true), 515u * 65u) << "the AO view's rays";

    const Scene box = loadScene(test::scenePath("cornell_box.json"), {"render.accel=none"});
    // Five walls and the light, 2 triangles each; two blocks of 10; 2 · 9 rays.
    EXPECT_EQ(flatLoopIterationsPerSample(box, true), (6u * 3u + 2u * 11u) * 18u);
    EXPECT_EQ(flatLoopIterationsPerSample(box, false), (6u * 3u + 2u * 11u) * 18u);
    EXPECT_FALSE(sceneFeatures(box).flatSteps);
    EXPECT_EQ(featureName(sceneFeatures(box)).find("flat-steps"), std::string::npos);
}

// The whole bound of a sample's loop iterations (boundedLoopIterationsPerSample), which sizes the
// draws: the searches as above, the path loop's step per bounce, and the samplers' own loops. The
// Cornell box has few objects whose meshes are small, so even under render.accel bvh its searches
// are plain loops: (6 · 3 + 2 · 11) · 18, plus 9 steps. The terrain's BVH walk has no bound.
TEST(BoundedLoopIterations, AddTheStepsAndTheSamplersLoopsToTheSearches) {
    const auto bound = [](const Scene& s, bool extraDefines = false) {
        return boundedLoopIterationsPerSample(s, sceneFeatures(s), extraDefines);
    };
    const std::uint64_t search = (6u * 3u + 2u * 11u) * 18u;
    const Scene box = loadScene(test::scenePath("cornell_box.json"), {"render.sampler=sobol"});
    EXPECT_EQ(bound(box), search + 9u);
    EXPECT_EQ(bound(loadScene(test::scenePath("cornell_box.json"), {"render.sampler=independent"})), search + 9u);
    EXPECT_EQ(bound(loadScene(test::scenePath("cornell_box.json"), {"render.sampler=zsobol"})),
              search + 9u * (1u + 4u * 12u) + 2u * 12u);
    EXPECT_EQ(bound(loadScene(test::scenePath("cornell_box.json"), {"render.sampler=stratified"})),
              search + 9u * (1u + 4u * 2u) + 2u * 2u);
    EXPECT_EQ(bound(box, true), 0u) << "the debug views' and counts' variants: only a flat search's bound";
    EXPECT_EQ(bound(loadScene(test::scenePath("cornell_box.json"), {"render.accel=none"}), true), search + 9u)
        << "a flat search counts without a BVH";

    Scene terrain = loadScene(test::scenePath("displaced_terrain.json"));
    EXPECT_EQ(bound(terrain), 0u) << "a BVH walk";
    terrain.render.accel = Accel::None;
    EXPECT_EQ(bound(terrain), flatLoopIterationsPerSample(terrain, true) + 7u * (1u + terrain.lights.size()));
}

// A ray that leaves an object on a side it cannot meet it again from (accel/escape_sides.h) does
// not search it. Rendered again with every object searched (RAYLAB_LEAVE_OUT_ESCAPED 0), the image
// may differ only where a search found the surface a ray left (a self-intersection), which is rare:
// the Cornell box's planar walls and convex blocks are left out of most rays' searches. Inside a
// closed cube wound outwards, every ray leaves a face on its back and must meet the cube again: a
// wrongly flagged cube would let the light out and the image go black.
TEST_F(AccelRenderTest, ARayLeavesOutTheObjectItLeavesOnlyWhereItCannotMeetItAgain) {
    const Scene cornell = small("cornell_box.json", "bvh", 16, 16);
    const Scene room = parseScene(R"({
        "camera": { "position": [0, 0, -3], "look_at": [0, 0, 1], "fov": 70 },
        "render": { "width": 24, "height": 16, "spp": 16, "rpp": 16, "max_bounces": 6, "adaptive": false },
        "sky": { "type": "constant", "color": 0 },
        "materials": { "wall": { "albedo": 0.7 }, "lamp": { "albedo": 0, "emission": [4, 4, 4], "strength": 1 } },
        "objects": [
          { "type": "mesh", "material": "wall",
            "positions": [-5, -5, -5,  5, -5, -5,  -5, 5, -5,  5, 5, -5,  -5, -5, 5,  5, -5, 5,  -5, 5, 5,  5, 5, 5],
            "indices": [0, 2, 1,  1, 2, 3,  4, 5, 6,  5, 7, 6,  0, 1, 4,  1, 5, 4,  2, 6, 3,  3, 6, 7,
                        0, 4, 2,  2, 4, 6,  1, 3, 5,  3, 7, 5] },
          { "type": "sphere", "center": [0, 3.5, 1], "radius": 0.6, "material": "lamp" }
        ] })", "room.json");
    for (const Scene* scene : {&cornell, &room}) {
        SCOPED_TRACE(scene == &cornell ? "cornell_box.json" : "room.json");
        const Image leaving = test::render(*scene);
        TracerOptions searchAll;
        searchAll.extraDefines = {{"RAYLAB_LEAVE_OUT_ESCAPED", "0"}};
        const Image all = test::render(*scene, searchAll);
        ASSERT_EQ(leaving.rgba.size(), all.rgba.size());
        double sumLeaving = 0.0, sumAll = 0.0;
        int differing = 0;
        for (std::size_t p = 0; p < leaving.rgba.size(); p += 4) {
            bool differs = false;
            for (int c = 0; c < 3; ++c) {
                sumLeaving += leaving.rgba[p + c];
                sumAll += all.rgba[p + c];
                differs |= leaving.rgba[p + c] != all.rgba[p + c];
            }
            differing += differs;
        }
        EXPECT_GT(sumAll, 0.0);
        EXPECT_LE(differing, 2) << "of " << leaving.rgba.size() / 4 << " pixels";
        EXPECT_NEAR(sumLeaving / sumAll, 1.0, 1e-3);
    }
}
