// BVH construction invariants, and the traversal (the shader's code run on the CPU, and on the GPU)
// against brute force on random scenes of spheres and transformed meshes.
#include "accel/bvh.h"
#include "accel/cpu_traversal.h"
#include "shaders/include/few_objects.glsl"
#include "scene/transform.h"
#include "scene/scene_loader.h"
#include "support/gl_test.h"
#include "support/far_objects.h"
#include "support/gpu_trace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace raylab;

namespace {

bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::greaterThanEqual(outer.max, inner.max));
}

// Random scene: spheres and meshes of random triangles, with random transforms.
Scene randomScene(std::uint32_t seed, int spheres, int meshes, int trianglesPerMesh) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Scene s;
    s.materials.push_back(Material{});
    for (int i = 0; i < spheres; ++i) {
        Sphere sp;
        sp.center = 10.0f * glm::vec3(u(rng), u(rng), u(rng));
        sp.radius = 0.2f + 0.8f * std::abs(u(rng));
        if (i % 2) {
            sp.transform.translation = glm::vec3(u(rng), u(rng), u(rng));
            sp.transform.rotation = 180.0f * glm::vec3(u(rng), u(rng), u(rng));
            sp.transform.scale = glm::vec3(1.0f + 0.5f * u(rng));
        }
        s.spheres.push_back(sp);
    }
    for (int m = 0; m < meshes; ++m) {
        Mesh mesh;
        for (int t = 0; t < trianglesPerMesh; ++t) {
            const glm::vec3 c = 3.0f * glm::vec3(u(rng), u(rng), u(rng));
            for (int k = 0; k < 3; ++k) mesh.positions.push_back(c + 0.4f * glm::vec3(u(rng), u(rng), u(rng)));
            const unsigned b = unsigned(3 * t);
            mesh.triangles.emplace_back(b, b + 1, b + 2);
        }
        mesh.transform.translation = 8.0f * glm::vec3(u(rng), u(rng), u(rng));
        mesh.transform.rotation = 180.0f * glm::vec3(u(rng), u(rng), u(rng));
        mesh.transform.scale = glm::vec3(1.0f + 0.5f * u(rng), 1.0f + 0.5f * u(rng), 1.0f + 0.5f * u(rng));
        s.meshes.push_back(mesh);
    }
    return s;
}

std::vector<test::TestRay> randomRays(std::uint32_t seed, int n) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<test::TestRay> rays;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 o = 15.0f * glm::vec3(u(rng), u(rng), u(rng));
        const glm::vec3 target = 8.0f * glm::vec3(u(rng), u(rng), u(rng));
        glm::vec3 d = target - o;
        if (i % 7 == 0) d.x = 0.0f;   // zero direction components
        if (i % 11 == 0) d.y = 0.0f;
        const float tMax = 1.5f * std::abs(u(rng));   // shadow query: part of the way to the target
        rays.push_back({glm::vec4(o, 0.0f), glm::vec4(d, tMax)});
    }
    return rays;
}

// Brute force over every object and triangle, with the same per-primitive code.
struct Reference {
    bool hit = false;
    glsl::TraceRecord rec{};
};

Reference bruteForce(const SceneGeometry& g, const Scene& scene, glsl::Ray ray, float tMax, bool anyHit) {
    Reference r;
    r.rec = glsl::TraceRecord(tMax, 0u, 0u, 0.0f, 0.0f);
    std::vector<std::uint32_t> firstTriangle;
    std::uint32_t offset = 0;
    for (const Mesh& m : scene.meshes) {
        firstTriangle.push_back(offset);
        offset += std::uint32_t(m.triangles.size());
    }
    for (std::uint32_t i = 0; i < g.instances.size(); ++i) {
        const glsl::GpuInstance& inst = g.instances[i];
        if (inst.info.x == glsl::INSTANCE_SPHERE) {
            const glm::vec4 s = g.spheres[inst.info.y].centerRadius;
            const float t = glsl::intersectSphere(ray, glm::vec3(s), s.w, 0.0f, r.rec.t);
            if (t > 0.0f) {
                r.rec = glsl::TraceRecord(t, i, inst.info.y, 0.0f, 0.0f);
                r.hit = true;
            }
            continue;
        }
        const std::size_t m = std::size_t(std::find(g.meshRoot.begin(), g.meshRoot.end(), inst.info.y) - g.meshRoot.begin());
        // The same object-space ray as the traversal: origin moved past its rounding error by dt.
        const glm::vec3 o = glsl::transformPoint(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2, ray.origin);
        const glm::vec3 d = glsl::transformVector(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2, ray.dir);
        const glm::vec3 oError = glsl::transformPointError(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2,
                                                          ray.origin, glm::vec3(0.0f));
        const float dt = glm::dot(glm::abs(d), oError) / glm::dot(d, d);
        const glsl::Ray local(o + dt * d, d);
        for (std::uint32_t k = 0; k < scene.meshes[m].triangles.size(); ++k) {
            const std::uint32_t ti = firstTriangle[m] + k;
            const glm::uvec4 v = g.triangles[ti].vertices;
            glsl::TriangleHit h{};
            if (glsl::intersectTriangle(local, glm::vec3(g.vertices[v.x].positionU), glm::vec3(g.vertices[v.y].positionU),
                                        glm::vec3(g.vertices[v.z].positionU), r.rec.t - dt, h)) {
                r.rec = glsl::TraceRecord(h.t + dt, i, ti, h.b1, h.b2);
                r.hit = true;
            }
        }
        if (anyHit && r.hit) return r;
    }
    return r;
}

// The GPU's answers for `rays` against the brute force: rays whose nearest hit and whose shadow
// verdict differ, hits, hits on meshes, and hits on another instance or primitive.
struct Agreement {
    int hitMiss = 0, occlusion = 0, hits = 0, meshHits = 0, mismatch = 0;
};

Agreement againstBruteForce(const SceneGeometry& g, const Scene& scene, const std::vector<test::TestRay>& rays,
                            const std::vector<test::GpuTraceResult>& results) {
    Agreement a;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const glsl::Ray ray(glm::vec3(rays[i].origin), glm::vec3(rays[i].dir));
        const Reference ref = bruteForce(g, scene, ray, glsl::FLOAT_MAX, false);
        a.hitMiss += (results[i].t >= 0.0f) != ref.hit;
        if (ref.hit) {
            ++a.hits;
            a.meshHits += g.instances[ref.rec.instance].info.x == glsl::INSTANCE_MESH;
            a.mismatch += results[i].instance != ref.rec.instance || results[i].primitive != ref.rec.primitive;
        }
        a.occlusion += results[i].occluded != bruteForce(g, scene, ray, rays[i].dir.w, true).hit;
    }
    return a;
}

} // namespace

TEST(Bvh, EveryPrimitiveOnceAndBoundsNest) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int n : {1, 2, 3, 17, 1000, 20000}) {
        std::vector<Aabb> boxes(static_cast<std::size_t>(n));
        for (Aabb& b : boxes) {
            const glm::vec3 c(100.0f * u(rng), 100.0f * u(rng), u(rng));
            b.grow(c);
            b.grow(c + glm::abs(glm::vec3(u(rng), u(rng), u(rng))));
        }
        if (n == 20000)
            for (int i = 0; i < 5000; ++i) boxes[std::size_t(i)] = boxes[0];   // many identical boxes
        const Bvh bvh = buildBvh(boxes);
        std::vector<int> seen(static_cast<std::size_t>(n), 0);
        for (std::uint32_t p : bvh.order) ++seen.at(p);
        for (int s : seen) ASSERT_EQ(s, 1) << n;
        std::size_t inLeaves = 0;
        for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
            const BvhNode& node = bvh.nodes[i];
            if (node.count > 0) {
                inLeaves += node.count;
                for (std::uint32_t k = node.index; k < node.index + node.count; ++k)
                    ASSERT_TRUE(contains(node.bounds, boxes[bvh.order[k]])) << n << " leaf " << i;
            } else {
                ASSERT_GT(node.index, i + 1);
                ASSERT_TRUE(contains(node.bounds, bvh.nodes[i + 1].bounds)) << n << " node " << i;
                ASSERT_TRUE(contains(node.bounds, bvh.nodes[node.index].bounds)) << n << " node " << i;
            }
        }
        EXPECT_EQ(inLeaves, std::size_t(n));
        EXPECT_LE(bvh.depth, 60) << "the GPU stack holds 64 entries";
        // SAH cost is at least that of testing the root's box and one primitive (n > 1), and far
        // below testing every primitive for a large random set.
        if (n >= 1000) {
            EXPECT_LT(bvh.sahCost(), 0.1 * n) << n;
        }
    }
}

TEST(Bvh, CpuTraversalMatchesBruteForceNearestAndShadow) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        const Scene scene = randomScene(seed, 40, 5, 200);
        const SceneGeometry g = buildSceneGeometry(scene);
        glsl::cpuTraversal.geometry = &g;
        int hits = 0, occludedCount = 0;
        for (const test::TestRay& tr : randomRays(seed + 100, 4000)) {
            const glsl::Ray ray(glm::vec3(tr.origin), glm::vec3(tr.dir));
            glsl::TraceRecord rec{};
            const bool hit = glsl::traceScene(ray, glsl::FLOAT_MAX, false, rec);
            const Reference ref = bruteForce(g, scene, ray, glsl::FLOAT_MAX, false);
            ASSERT_EQ(hit, ref.hit);
            if (hit) {
                ++hits;
                ASSERT_EQ(rec.t, ref.rec.t);
                ASSERT_EQ(rec.instance, ref.rec.instance);
                ASSERT_EQ(rec.primitive, ref.rec.primitive);
            }
            const bool occ = glsl::occludedBvh(ray, tr.dir.w);
            ASSERT_EQ(occ, bruteForce(g, scene, ray, tr.dir.w, true).hit);
            occludedCount += occ;
        }
        EXPECT_GT(hits, 500) << "the test should exercise hits";
        EXPECT_GT(occludedCount, 200);
        EXPECT_LT(occludedCount, hits);
    }
    glsl::cpuTraversal.geometry = nullptr;
}

// render.accel boxes and none (flat_traversal.glsl) find exactly the BVH's hits, and pay for it: a
// box per object per ray (boxes), more triangles than the BVH (boxes), every triangle (none).
TEST(Bvh, FlatTraversalsFindTheBvhsHitsAtAHigherCost) {
    auto check = [](const Scene& scene, const std::vector<test::TestRay>& rays, const std::string& name) {
        const SceneGeometry g = buildSceneGeometry(scene);
        glsl::cpuTraversal.geometry = &g;
        std::uint64_t triangles[3] = {}, boxes[3] = {};
        int hits = 0;
        for (const test::TestRay& tr : rays) {
            const glsl::Ray ray(glm::vec3(tr.origin), glm::vec3(tr.dir));
            glsl::TraceRecord recs[3] = {};
            bool found[3] = {}, occluded[3] = {};
            for (int mode = 0; mode < 3; ++mode) {
                glsl::cpuTraversal.boxTests = glsl::cpuTraversal.triangleTests = 0;
                found[mode] = mode == 0 ? glsl::traceScene(ray, glsl::FLOAT_MAX, false, recs[mode])
                                        : glsl::traceSceneFlat(ray, glsl::FLOAT_MAX, false, mode == 1, recs[mode]);
                triangles[mode] += glsl::cpuTraversal.triangleTests;
                boxes[mode] += glsl::cpuTraversal.boxTests;
                glsl::TraceRecord any{};
                occluded[mode] = mode == 0 ? glsl::traceScene(ray, tr.dir.w, true, any)
                                           : glsl::traceSceneFlat(ray, tr.dir.w, true, mode == 1, any);
            }
            hits += found[0];
            for (int mode = 1; mode < 3; ++mode) {
                ASSERT_EQ(found[mode], found[0]) << name << " mode " << mode;
                ASSERT_EQ(occluded[mode], occluded[0]) << name << " mode " << mode;
                if (!found[0]) continue;
                ASSERT_EQ(recs[mode].t, recs[0].t) << name << " mode " << mode;
                ASSERT_EQ(recs[mode].instance, recs[0].instance) << name << " mode " << mode;
                ASSERT_EQ(recs[mode].primitive, recs[0].primitive) << name << " mode " << mode;
            }
        }
        EXPECT_GT(hits, int(rays.size()) / 20) << name << ": the test should exercise hits";
        EXPECT_EQ(boxes[1], std::uint64_t(rays.size()) * g.instances.size()) << name << ": one box per object and ray";
        EXPECT_EQ(boxes[2], 0u) << name;
        EXPECT_GT(triangles[1], triangles[0]) << name;
        EXPECT_EQ(triangles[2], std::uint64_t(rays.size()) * g.triangles.size()) << name << ": every triangle, every ray";
        glsl::cpuTraversal.geometry = nullptr;
    };
    for (std::uint32_t seed : {1u, 2u}) check(randomScene(seed, 40, 5, 200), randomRays(seed + 100, 4000), "random");
    // The Cornell box's walls and blocks from the camera, towards points in and around the box.
    const Scene cornell = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/cornell_box.json");
    std::vector<test::TestRay> fromCamera;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 1500; ++i) {
        const glm::vec3 target = glm::vec3(278.0f, 274.0f, 280.0f) + 300.0f * glm::vec3(u(rng), u(rng), u(rng));
        fromCamera.push_back({glm::vec4(cornell.camera.position, 0.0f),
                              glm::vec4(target - cornell.camera.position, std::abs(u(rng)))});
    }
    check(cornell, fromCamera, "cornell_box");
}

TEST(Bvh, MovingAnObjectOnlyRebuildsTheTopLevel) {
    Scene scene = randomScene(9, 3, 2, 100);
    SceneGeometry g = buildSceneGeometry(scene);
    const auto meshNodes = g.meshNodes.size();
    const auto firstNode = g.meshNodes[0].boundsMin;
    scene.meshes[0].transform.translation += glm::vec3(100.0f, 0.0f, 0.0f);
    updateTopLevel(g, scene);
    EXPECT_EQ(g.meshNodes.size(), meshNodes);
    EXPECT_EQ(g.meshNodes[0].boundsMin, firstNode);
    // The moved mesh is found where it went.
    glsl::cpuTraversal.geometry = &g;
    const glm::vec3 c = glm::vec3(transformMatrix(scene.meshes[0].transform) * glm::vec4(scene.meshes[0].positions[0], 1.0f));
    const glsl::Ray ray(c + glm::vec3(0.0f, 0.0f, 50.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    glsl::TraceRecord rec{};
    ASSERT_TRUE(glsl::traceScene(ray, glsl::FLOAT_MAX, false, rec));
    EXPECT_EQ(bruteForce(g, scene, ray, glsl::FLOAT_MAX, false).rec.instance, rec.instance);
    glsl::cpuTraversal.geometry = nullptr;
}

TEST(Bvh, TriangleRecordsCarryThePositionsOfTheirVertices) {
    const Scene scene = randomScene(11, 0, 3, 50);
    const SceneGeometry g = buildSceneGeometry(scene);
    ASSERT_EQ(g.triangles.size(), 150u);
    for (std::size_t t = 0; t < g.triangles.size(); ++t) {
        const glsl::GpuTriangle& tri = g.triangles[t];
        EXPECT_EQ(glm::vec3(tri.p0), glm::vec3(g.vertices.at(tri.vertices.x).positionU)) << "triangle " << t;
        EXPECT_EQ(glm::vec3(tri.p1), glm::vec3(g.vertices.at(tri.vertices.y).positionU)) << "triangle " << t;
        EXPECT_EQ(glm::vec3(tri.p2), glm::vec3(g.vertices.at(tri.vertices.z).positionU)) << "triangle " << t;
    }
}

class BvhGpuTest : public test::GlTest {};

TEST_F(BvhGpuTest, GpuTraversalMatchesBruteForceNearestAndShadow) {
    const Scene scene = randomScene(5, 40, 5, 200);
    GpuScene gpu;
    gpu.upload(scene);
    const SceneGeometry& g = gpu.geometry();
    const std::vector<test::TestRay> rays = randomRays(77, 4000);
    const std::vector<test::GpuTraceResult> results = test::gpuTrace(gpu, rays);
    int hits = 0, primitiveMismatch = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const glsl::Ray ray(glm::vec3(rays[i].origin), glm::vec3(rays[i].dir));
        const Reference ref = bruteForce(g, scene, ray, glsl::FLOAT_MAX, false);
        ASSERT_EQ(results[i].t >= 0.0f, ref.hit) << "ray " << i;
        if (ref.hit) {
            ++hits;
            EXPECT_NEAR(results[i].t, ref.rec.t, 1e-5f * ref.rec.t) << "ray " << i;
            primitiveMismatch += results[i].instance != ref.rec.instance || results[i].primitive != ref.rec.primitive;
        }
        ASSERT_EQ(results[i].occluded, bruteForce(g, scene, ray, rays[i].dir.w, true).hit) << "ray " << i;
    }
    EXPECT_GT(hits, 500);
    EXPECT_EQ(primitiveMismatch, 0);
}

// A ray along +z from the origin past the edge p1 p2, whose edge function is -2^-24 exactly and 0
// in float: the recomputation in double (triangle.glsl) gives it its sign, so the triangle misses
// with p0 across that edge from the ray and is hit with p0 on the ray's side, on the device as on
// the host; a ray 1e-3 further out misses either way.
TEST_F(BvhGpuTest, EdgeFunctionsThatRoundToZeroGetTheirExactSignOnTheDeviceAsOnTheHost) {
    const float e = std::ldexp(1.0f, -12);
    const glm::vec3 p1(1.0f + e, 1.0f + 2.0f * e, 1.0f), p2(-1.0f, -1.0f - e, 1.0f);
    struct Case {
        glm::vec3 p0;
        glm::vec3 origin;
        bool hit;
    };
    const Case cases[] = {{{1.0f, -1.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, false},   // outside by 2^-24
                          {{-1.0f, 1.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, true},    // inside by 2^-24
                          {{1.0f, -1.0f, 1.0f}, {-1e-3f, 1e-3f, 0.0f}, false},
                          {{-1.0f, 1.0f, 1.0f}, {1e-3f, -1e-3f, 0.0f}, false}};
    for (int i = 0; i < 4; ++i) {
        const Case& c = cases[i];
        const glsl::Ray ray(c.origin, glm::vec3(0.0f, 0.0f, 1.0f));
        glsl::TriangleHit h{};
        EXPECT_EQ(glsl::intersectTriangle(ray, c.p0, p1, p2, glsl::FLOAT_MAX, h), c.hit) << "host, case " << i;
        Scene scene;
        scene.materials.push_back(Material{});
        Mesh mesh;
        mesh.positions = {c.p0, p1, p2};
        mesh.triangles.emplace_back(0, 1, 2);
        scene.meshes.push_back(mesh);
        GpuScene gpu;
        gpu.upload(scene);
        const std::vector<test::GpuTraceResult> r =
            test::gpuTrace(gpu, {test::TestRay{glm::vec4(ray.origin, 0.0f), glm::vec4(ray.dir, glsl::FLOAT_MAX)}});
        EXPECT_EQ(r.at(0).t >= 0.0f, c.hit) << "device, case " << i;
        EXPECT_EQ(r.at(0).occluded, c.hit) << "device, case " << i;
    }
}

// The linear top level (few objects) loops over the spheres and boxes of its uniform block
// (few_objects.glsl) and names each hit's instance through the sphere's back-link: the same
// records as the brute force, with and without meshes in the shader, for as many objects as the
// block holds.
TEST_F(BvhGpuTest, LinearTopLevelMatchesBruteForceWithAndWithoutMeshes) {
    for (const int meshes : {0, 3}) {
        const Scene scene = randomScene(11, glsl::FEW_OBJECTS_MAX - meshes, meshes, 60);
        ASSERT_EQ(scene.spheres.size() + scene.meshes.size(), std::size_t(glsl::FEW_OBJECTS_MAX));
        GpuScene gpu;
        gpu.upload(scene);
        const SceneGeometry& g = gpu.geometry();
        for (std::size_t i = 0; i < g.instances.size(); ++i) {
            if (g.instances[i].info.x == glsl::INSTANCE_SPHERE) {
                EXPECT_EQ(g.spheres[g.instances[i].info.y].info.y, i);
            }
        }
        ShaderDefines defines = {{"RAYLAB_FEATURES_SPECIALISED", "1"}, {"RAYLAB_FEATURE_SPHERES", "1"},
                                 {"RAYLAB_TOP_LEVEL_LINEAR", "1"}};
        if (meshes > 0) defines.push_back({"RAYLAB_FEATURE_MESHES", "1"});
        const std::vector<test::TestRay> rays = randomRays(78, 4000);
        const Agreement a = againstBruteForce(g, scene, rays, test::gpuTrace(gpu, rays, defines));
        EXPECT_EQ(a.hitMiss, 0) << "meshes " << meshes;
        EXPECT_EQ(a.occlusion, 0) << "meshes " << meshes;
        EXPECT_GT(a.hits, 200) << "meshes " << meshes;
        EXPECT_EQ(a.mismatch, 0) << "meshes " << meshes;
    }
}


// Small meshes with their transforms baked into their vertices (RAYLAB_MESHES_IN_WORLD): every
// mesh placed by the identity, rays and hits taken as they are, each lane's boxes noted first and
// their triangles tested in one loop. The same records as the brute force.
TEST_F(BvhGpuTest, MeshesInWorldMatchBruteForce) {
    Scene scene = randomScene(12, 9, 5, 12);
    for (Mesh& m : scene.meshes) m.transform = scene.meshes[0].transform;   // together, where the rays go
    GpuScene gpu;
    gpu.upload(scene);
    const SceneGeometry& g = gpu.geometry();
    ASSERT_TRUE(g.meshesInWorld);
    for (const glsl::GpuInstance& inst : g.instances) {
        if (inst.info.x != glsl::INSTANCE_MESH) continue;
        EXPECT_EQ(inst.worldToObject0, glm::vec4(1, 0, 0, 0));
        EXPECT_EQ(inst.worldToObject2, glm::vec4(0, 0, 1, 0));
        EXPECT_EQ(inst.objectToWorld1, glm::vec4(0, 1, 0, 0));
    }
    const ShaderDefines defines = {{"RAYLAB_FEATURES_SPECIALISED", "1"}, {"RAYLAB_FEATURE_SPHERES", "1"},
                                   {"RAYLAB_FEATURE_MESHES", "1"},       {"RAYLAB_TOP_LEVEL_LINEAR", "1"},
                                   {"RAYLAB_SMALL_MESHES", "1"},         {"RAYLAB_MESHES_IN_WORLD", "1"}};
    const std::vector<test::TestRay> rays = randomRays(79, 16000);
    const Agreement a = againstBruteForce(g, scene, rays, test::gpuTrace(gpu, rays, defines));
    EXPECT_EQ(a.hitMiss, 0);
    EXPECT_EQ(a.occlusion, 0);
    EXPECT_GT(a.meshHits, 100);
    EXPECT_EQ(a.mismatch, 0);
}


TEST_F(BvhGpuTest, HugeCoordinatesThroughTheGpuBvhHaveNoMissesAndNoNan) {
    // The scene and rays of IntersectionStress.HugeCoordinatesThroughTheBvh* (unit spheres and
    // triangles up to 10^6 from the origin, placed by coordinates or translations) through the
    // shader on the GPU, whose float arithmetic may differ from the CPU's (fused multiply-adds):
    // every ray that must hit its object finds it, at a finite t, and every hit is finite.
    const Scene scene = test::farObjectsScene(400, 9);
    GpuScene gpu;
    gpu.upload(scene);
    const std::vector<test::AimedRay> aimed = test::raysAtEachObject(gpu.geometry(), 100, 10);
    std::vector<test::TestRay> rays;
    for (const test::AimedRay& a : aimed)
        rays.push_back({glm::vec4(a.ray.origin, 0.0f), glm::vec4(a.ray.dir, 10.0f)});
    const std::vector<test::GpuTraceResult> results = test::gpuTrace(gpu, rays);
    int missing = 0, demanded = 0, nonFinite = 0, notOccluding = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const test::GpuTraceResult& r = results[i];
        nonFinite += !std::isfinite(r.t);
        if (!aimed[i].mustHit) continue;
        ++demanded;
        missing += r.t < 0.0f || r.instance != aimed[i].instance;
        notOccluding += !r.occluded;   // the object is met at t <= 1 < tMax = 10
    }
    EXPECT_EQ(nonFinite, 0);
    EXPECT_EQ(missing, 0) << "of " << demanded << " demanded hits";
    EXPECT_EQ(notOccluding, 0);
    EXPECT_GT(demanded, 30000);
}
