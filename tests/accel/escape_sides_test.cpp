// Which side of its surface a ray can leave an object by and never meet it again
// (accel/escape_sides.h): planar meshes both, convex ones the side their windings face, folds one,
// anything else neither; and the CPU traversal leaves that instance out of the search.
#include "accel/cpu_traversal.h"
#include "accel/escape_sides.h"
#include "scene/scene_loader.h"
#include "render/render_helpers.h"

#include <gtest/gtest.h>

#include <bit>

using namespace raylab;

namespace {

constexpr unsigned kFront = glsl::INSTANCE_ESCAPES_FRONT;
constexpr unsigned kBack = glsl::INSTANCE_ESCAPES_BACK;

Mesh mesh(std::vector<glm::vec3> positions, std::vector<glm::uvec3> triangles) {
    Mesh m;
    m.positions = std::move(positions);
    m.triangles = std::move(triangles);
    return m;
}

// The unit cube [0, 1]³ with every winding facing outwards.
Mesh cube(glm::vec3 offset = glm::vec3(0.0f)) {
    std::vector<glm::vec3> p;
    for (int i = 0; i < 8; ++i) p.push_back(offset + glm::vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    return mesh(p, {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},     // z = 0 (−z), z = 1 (+z)
                    {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},     // y = 0 (−y), y = 1 (+y)
                    {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}});   // x = 0 (−x), x = 1 (+x)
}

Mesh reversed(Mesh m) {
    for (glm::uvec3& t : m.triangles) std::swap(t.y, t.z);
    return m;
}

Mesh joined(const Mesh& a, const Mesh& b) {
    Mesh m = a;
    const auto offset = unsigned(a.positions.size());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    for (const glm::uvec3& t : b.triangles) m.triangles.push_back(t + glm::uvec3(offset));
    return m;
}

} // namespace

TEST(EscapeSides, ConvexMeshesEscapeOnTheSideTheirWindingsFace) {
    const Mesh quad = mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
    EXPECT_EQ(meshEscapeSides(quad), kFront | kBack) << "planar: both sides";
    EXPECT_EQ(meshEscapeSides(cube()), kFront) << "closed, wound outwards";
    EXPECT_EQ(meshEscapeSides(reversed(cube())), kBack) << "closed, wound inwards";
    Mesh open = cube();
    open.triangles.resize(10);   // no x = 1 face: the rest still lies behind every face's plane
    EXPECT_EQ(meshEscapeSides(open), kFront);
    // A fold: the second triangle bends down, behind the first's plane; the first lies behind the
    // second's. Leaving either towards the back, a ray may meet the other.
    const Mesh fold = mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, -0.5f}}, {{0, 1, 2}, {0, 2, 3}});
    EXPECT_EQ(meshEscapeSides(fold), kFront);
    EXPECT_EQ(meshEscapeSides(reversed(fold)), kBack);
}

TEST(EscapeSides, AnythingElseEscapesOnNeitherSide) {
    EXPECT_EQ(meshEscapeSides(joined(cube(), cube(glm::vec3(3, 0, 0)))), 0u) << "two cubes: each in front of the other's faces";
    const Mesh zigzag = mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, -0.5f}, {0, 2, 0}},
                             {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}});
    EXPECT_EQ(meshEscapeSides(zigzag), 0u) << "bent down, then up again";
    EXPECT_EQ(meshEscapeSides(Mesh{}), 0u) << "no triangles";
    // A vertex a float step off the plane is off it: 1e-12 of the size is the tolerance.
    const Mesh almost = mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-7f}}, {{0, 1, 2}, {0, 2, 3}});
    EXPECT_EQ(meshEscapeSides(almost), kBack) << "a fold, the other way up";
    // A degenerate triangle has no plane to leave by and does not change the answer.
    const Mesh withSliver = mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}},
                                 {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}});
    EXPECT_EQ(meshEscapeSides(withSliver), kFront | kBack);
}

TEST(EscapeSides, LargeMeshesAreNotExamined) {
    Mesh strip;   // planar, but triangles × vertices over kEscapeSidesMaxWork
    const int n = 2100;
    for (int i = 0; i <= n; ++i) {
        strip.positions.push_back(glm::vec3(float(i), 0.0f, 0.0f));
        strip.positions.push_back(glm::vec3(float(i), 1.0f, 0.0f));
    }
    for (unsigned i = 0; i < unsigned(n); ++i) {
        strip.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
        strip.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
    }
    ASSERT_GT(strip.triangles.size() * strip.positions.size(), kEscapeSidesMaxWork);
    EXPECT_EQ(meshEscapeSides(strip), 0u);
    strip.positions.resize(2 * 200 + 2);
    strip.triangles.resize(2 * 200);
    EXPECT_EQ(meshEscapeSides(strip), kFront | kBack);
}

TEST(EscapeSides, TheCornellBoxsWallsLightAndBlocksAndTheirInstances) {
    const Scene scene = loadScene(test::scenePath("cornell_box.json"));
    ASSERT_EQ(scene.meshes.size(), 8u);
    // floor, ceiling, back, right, left, light, short block, tall block. The left wall's corners
    // (Cornell's measured data) do not lie in one plane: a fold, open to one side only.
    const unsigned planar = kFront | kBack;
    for (int m : {0, 1, 2, 3, 5}) EXPECT_EQ(meshEscapeSides(scene.meshes[std::size_t(m)]), planar) << m;
    EXPECT_EQ(std::popcount(meshEscapeSides(scene.meshes[4])), 1) << "left wall";
    EXPECT_EQ(std::popcount(meshEscapeSides(scene.meshes[6])), 1) << "short block";
    EXPECT_EQ(std::popcount(meshEscapeSides(scene.meshes[7])), 1) << "tall block";
    const SceneGeometry g = buildSceneGeometry(scene);
    for (const glsl::GpuInstance& inst : g.instances) {
        const unsigned object = glsl::instanceObjectId(inst);
        ASSERT_LT(object, 8u);
        EXPECT_EQ(inst.info.w & planar, meshEscapeSides(scene.meshes[object])) << object;
        EXPECT_EQ(inst.info.w & glsl::INSTANCE_HAS_NORMALS, 0u);
    }
}

TEST(EscapeSides, TheSearchLeavesOutTheInstanceTheRayLeaves) {
    // A ray from inside a closed cube (wound outwards) meets the cube; told it leaves the cube it
    // misses, which is why only the side the flags name may be left out.
    Scene scene;
    scene.materials.push_back(Material{});
    scene.meshes.push_back(cube());
    const SceneGeometry g = buildSceneGeometry(scene);
    glsl::cpuTraversal.geometry = &g;
    const glsl::Ray ray(glm::vec3(0.5f), glm::vec3(1.0f, 0.2f, 0.1f));
    glsl::TraceRecord rec{};
    ASSERT_TRUE(glsl::traceScene(ray, glsl::FLOAT_MAX, false, rec));
    EXPECT_NEAR(rec.t, 0.5f, 1e-5f);
    EXPECT_FALSE(glsl::traceScene(ray, glsl::FLOAT_MAX, false, rec.instance, rec));
    EXPECT_TRUE(glsl::traceScene(ray, glsl::FLOAT_MAX, false, rec.instance + 1u, rec)) << "another instance: searched";
    glsl::cpuTraversal.geometry = nullptr;
}
