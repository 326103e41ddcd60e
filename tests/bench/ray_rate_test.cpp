// The ray-rate benchmark (bench/ray_rate.h): its ray sets are reproducible, its GPU ray cast finds
// the hits the CPU traversal finds, Embree (when built in) agrees with both, and the CLI writes
// the table, or says that Embree was not found.
#include "accel/cpu_traversal.h"
#include "bench/embree_peer.h"
#include "bench/ray_rate.h"
#include "scene/scene_loader.h"
#include "support/gl_test.h"

#include "shaders/include/bindings.glsl"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace raylab;

// The ray cast binds its buffers beside the scene's geometry.
static_assert(BINDING_CAST_RAYS != BINDING_CAST_HITS);
static_assert([] {
    for (int b : std::array{BINDING_SPHERES, BINDING_MATERIALS, BINDING_TOP_NODES, BINDING_MESH_NODES, BINDING_INSTANCES,
                            BINDING_TRIANGLES, BINDING_VERTICES, BINDING_TEXTURE_INFO})
        if (b == BINDING_CAST_RAYS || b == BINDING_CAST_HITS) return false;
    return true;
}());

namespace {

// Spheres, a turned and scaled box and a floor: both instance kinds, transforms and shared edges.
Scene tinyScene() {
    return parseScene(R"({
  "camera": { "position": [0, 1.5, 5], "look_at": [0, 0.5, 0], "fov": 50 },
  "render": { "width": 64, "height": 48 },
  "objects": [
    { "type": "sphere", "center": [-1.2, 0.5, 0], "radius": 0.5 },
    { "type": "sphere", "center": [1.3, 0.4, 0.5], "radius": 0.4 },
    { "type": "mesh", "positions": [-4, 0, -4, 4, 0, -4, 4, 0, 4, -4, 0, 4], "indices": [0, 2, 1, 0, 3, 2] },
    { "type": "mesh",
      "positions": [-1,-1,-1, 1,-1,-1, 1,1,-1, -1,1,-1, -1,-1,1, 1,-1,1, 1,1,1, -1,1,1],
      "indices": [0,2,1, 0,3,2, 4,5,6, 4,6,7, 0,1,5, 0,5,4, 3,7,6, 3,6,2, 0,4,7, 0,7,3, 1,2,6, 1,6,5],
      "transform": { "translation": [0.2, 0.6, -0.5], "rotation": [10, 35, 0], "scale": [0.6, 0.6, 0.4] } }
  ] })",
                      "tiny.json");
}

std::size_t hits(const std::vector<CastHit>& h) {
    return std::size_t(std::count_if(h.begin(), h.end(), [](const CastHit& x) { return x.t != glsl::CAST_MISS; }));
}

} // namespace

TEST(RayRateSets, AreTheSameForASeedAndBounceRaysLeaveTheSurface) {
    const Scene scene = tinyScene();
    const SceneGeometry g = buildSceneGeometry(scene);
    const RaySet a = cameraRays(scene, 32, 24, 7), b = cameraRays(scene, 32, 24, 7), c = cameraRays(scene, 32, 24, 8);
    ASSERT_EQ(a.rays.size(), 32u * 24u);
    EXPECT_EQ(0, std::memcmp(a.rays.data(), b.rays.data(), a.rays.size() * sizeof(CastRay)));
    EXPECT_NE(0, std::memcmp(a.rays.data(), c.rays.data(), a.rays.size() * sizeof(CastRay)));
    const std::vector<CastHit> first = castOnCpu(g, a);
    const RaySet bounce = bounceRays(g, a, 7);
    EXPECT_EQ(bounce.rays.size(), hits(first));   // one bounce per camera hit
    EXPECT_GT(bounce.rays.size(), a.rays.size() / 2);
    // Leaving the surface: no bounce ray meets its own surface at t ≈ 0.
    for (const CastHit& h : castOnCpu(g, bounce))
        if (h.t != glsl::CAST_MISS) {
            EXPECT_GT(h.t, 1e-3f);
        }
    const RaySet again = bounceRays(g, a, 7);
    EXPECT_EQ(0, std::memcmp(bounce.rays.data(), again.rays.data(), bounce.rays.size() * sizeof(CastRay)));
}

TEST(RayRateAgreement, CountsHitMissAndDistanceDisagreements) {
    const std::vector<CastRay> rays(4, CastRay(glm::vec4(0.0f), glm::vec4(0, 0, 1, glsl::FLOAT_MAX)));
    const std::vector<CastHit> a = {{1.0f, 0, 0, 0}, {glsl::CAST_MISS, 0, 0, 0}, {2.0f, 0, 0, 0}, {3.0f, 0, 0, 0}};
    const std::vector<CastHit> b = {{1.0f, 0, 0, 0}, {5.0f, 0, 0, 0}, {2.1f, 0, 0, 0}, {3.0f * (1 + 1e-5f), 0, 0, 0}};
    const Agreement g = compareHits(rays, a, b);
    EXPECT_EQ(g.rays, 4u);
    EXPECT_EQ(g.hitMiss, 1u);
    EXPECT_EQ(g.distance, 1u);
    EXPECT_DOUBLE_EQ(g.fraction(), 0.5);
    // Far from the origin the same difference in t is within the rounding of the coordinates.
    const std::vector<CastRay> far(4, CastRay(glm::vec4(1000, 0, 0, 0), glm::vec4(0, 0, 1, glsl::FLOAT_MAX)));
    EXPECT_EQ(compareHits(far, a, b).distance, 0u);
}

class RayRateGpu : public test::GlTest {};

TEST_F(RayRateGpu, RayCastFindsTheHitsOfTheCpuTraversal) {
    const Scene scene = tinyScene();
    GpuRayCaster caster(scene);
    const RaySet camera = cameraRays(scene, 64, 48, 1);
    const RaySet bounce = bounceRays(caster.geometry(), camera, 1);
    for (const RaySet* set : {&camera, &bounce}) {
        caster.setRays(*set);
        EXPECT_GT(caster.cast(), 0.0);
        const std::vector<CastHit> gpu = caster.hits(), cpu = castOnCpu(caster.geometry(), *set);
        ASSERT_EQ(gpu.size(), set->rays.size());
        const Agreement g = compareHits(set->rays, gpu, cpu, 1e-5f);
        EXPECT_EQ(g.hitMiss + g.distance, 0u) << set->name;
        std::size_t samePrimitive = 0;
        for (std::size_t i = 0; i < gpu.size(); ++i)
            samePrimitive += gpu[i].t == glsl::CAST_MISS ||
                             (gpu[i].instance == cpu[i].instance && gpu[i].primitive == cpu[i].primitive);
        EXPECT_EQ(samePrimitive, gpu.size()) << set->name;
        EXPECT_GT(hits(gpu), gpu.size() / 10) << set->name;   // the test compares hits, not only misses
    }
}

TEST(RayRateEmbree, AgreesWithTheCpuTraversal) {
    if (!embreeAvailable()) GTEST_SKIP() << "Embree not found: built without libembree-dev (RAYLAB_WITH_EMBREE)";
    const Scene scene = tinyScene();
    const SceneGeometry g = buildSceneGeometry(scene);
    const EmbreePeer peer(scene);
    const RaySet camera = cameraRays(scene, 64, 48, 3);
    for (const RaySet& set : {camera, bounceRays(g, camera, 3)}) {
        const std::vector<CastHit> cpu = castOnCpu(g, set);
        for (int packets : {1, 8, 16}) {
            std::vector<CastHit> embree;
            peer.cast(set.rays, embree, 2, packets);
            const Agreement a = compareHits(set.rays, embree, cpu);
            // Watertight against Embree's edge test: a ray through an exact shared edge may differ.
            EXPECT_GE(a.fraction(), 0.999) << set.name << " ×" << packets << ": " << a.hitMiss << " hit/miss, "
                                           << a.distance << " t";
        }
    }
}

TEST(RayRateCli, WritesTheTableBelowTheMarkerAndNamesAMissingEmbree) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_rays_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path out = dir / "rays.md";
    std::ofstream(out) << "# hand-written\n" << kRayRateMarker << "\nold table\n";
    const std::string cmd = std::string("cd '") + RAYLAB_SOURCE_DIR + "' && '" + RAYLAB_BENCH_EXE +
                            "' rays --scene scenes/cornell_box.json --rays 1024 --repeat 1 --out '" + out.string() +
                            "' > '" + (dir / "log.txt").string() + "' 2>&1";
    const int raw = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    std::stringstream log, text;
    log << std::ifstream(dir / "log.txt").rdbuf();
    ASSERT_EQ(WEXITSTATUS(raw), 0) << log.str();
    text << std::ifstream(out).rdbuf();
    const std::string s = text.str();
    EXPECT_EQ(s.rfind("# hand-written\n", 0), 0u) << s;
    EXPECT_EQ(s.find("old table"), std::string::npos) << s;
    for (const char* needle : {"| cornell_box.json | 32 | 1024 camera |", "bounce |", "- machine: ", "load average",
                               "- command: `", "--rays 1024"})
        EXPECT_NE(s.find(needle), std::string::npos) << needle << "\n" << s;
    const bool saysMissing = log.str().find("Embree not found") != std::string::npos &&
                             s.find("Embree not found") != std::string::npos;
    EXPECT_EQ(saysMissing, !embreeAvailable()) << log.str() << s;
    if (embreeAvailable()) {
        EXPECT_NE(s.find("- Embree: " + embreeVersion()), std::string::npos) << s;
    }
    fs::remove_all(dir);
}

TEST(RayRateCli, ABadSceneIsBadInputWithItsLocation) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_rays_bad_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "bad.json") << "{ \"objects\": [ { \"type\": \"sphere\", \"radius\": -1 } ] }\n";
    const std::string cmd = std::string("'") + RAYLAB_BENCH_EXE + "' rays --scene '" + (dir / "bad.json").string() +
                            "' --rays 16 --repeat 1 > '" + (dir / "log.txt").string() + "' 2>&1";
    const int raw = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    std::stringstream log;
    log << std::ifstream(dir / "log.txt").rdbuf();
    EXPECT_EQ(WEXITSTATUS(raw), 1) << log.str();
    EXPECT_NE(log.str().find("bad.json:1:"), std::string::npos) << log.str();
    fs::remove_all(dir);
}
