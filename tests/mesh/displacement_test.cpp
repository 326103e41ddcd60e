// Displacement on loading (mesh/displacement.h, mesh/subdivision.h): subdivision counts and
// closedness, heights from the texture at known points, recomputed normals of known shapes, the
// BVH's view of the displaced surface, the scene writer, the statistics, and the live keys that
// displace a loaded mesh again (objects.N.displacement_*).
#include "accel/cpu_traversal.h"
#include "mesh/displacement.h"
#include "mesh/subdivision.h"
#include "render/scene_stats.h"
#include "scene/scene_keys.h"
#include "scene/scene_loader.h"
#include "scene/scene_writer.h"
#include "support/gltf_writer.h"
#include "support/render_cli.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <utility>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return test::scratchDir("raylab_displace_" + name); }

// 8 × 1 texels; texel i has red `red(i)`, green 255 − red (must be ignored), blue 0.
void writeRow(const fs::path& path, int (*red)(int)) {
    std::vector<unsigned char> px;
    for (int i = 0; i < 8; ++i) px.insert(px.end(), {(unsigned char)red(i), (unsigned char)(255 - red(i)), 0});
    test::writePng(path, 8, 1, 3, px);
}

// The quad x, y in [-1, 1] at z = 0 (front e01 × e02 = +z), uv = (x + 1) / 2, (y + 1) / 2.
std::string quadScene(const std::string& displacement) {
    return R"({ "objects": [ { "type": "mesh", "positions": [-1,-1,0, 1,-1,0, 1,1,0, -1,1,0], "indices": [0,1,2, 0,2,3],
  "uvs": [0,0, 1,0, 1,1, 0,1], )" + displacement + " } ] }";
}

Scene load(const fs::path& dir, const std::string& text) {
    std::ofstream(dir / "scene.json") << text;
    return loadScene(dir / "scene.json");
}

// Every undirected edge and how many triangles use it.
std::map<std::pair<unsigned, unsigned>, int> edgeUses(const Mesh& m) {
    std::map<std::pair<unsigned, unsigned>, int> uses;
    for (const glm::uvec3& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const unsigned a = t[k], b = t[(k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    return uses;
}

// A regular octahedron with radial unit normals: a closed mesh, front faces outwards.
Mesh octahedron() {
    Mesh m;
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    m.normals = m.positions;
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

} // namespace

TEST(MeshSubdivision, EachLevelSplitsEveryTriangleIntoFourAndAClosedMeshStaysClosed) {
    const Mesh closed = octahedron();
    for (int level = 0; level <= 4; ++level) {
        const Mesh m = subdivideMesh(closed, level);
        const std::size_t faces = 8u << (2 * level);
        EXPECT_EQ(m.triangles.size(), faces) << level;
        const auto uses = edgeUses(m);
        for (const auto& [edge, n] : uses) EXPECT_EQ(n, 2) << "edge " << edge.first << "-" << edge.second << ", level " << level;
        // Euler's formula of a sphere: V − E + F = 2, so the midpoints are shared, never doubled.
        EXPECT_EQ(long(m.positions.size()) - long(uses.size()) + long(faces), 2) << level;
        EXPECT_EQ(m.normals.size(), m.positions.size());
    }
    // One triangle: (2^n + 1)(2^n + 2) / 2 vertices, each on the flat triangle.
    Mesh one;
    one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    one.uvs = {{0, 0}, {1, 0}, {0, 1}};
    one.triangles = {{0, 1, 2}};
    one.triangleMaterials = {3};
    const Mesh three = subdivideMesh(one, 3);
    EXPECT_EQ(three.positions.size(), 45u);
    EXPECT_EQ(three.triangles.size(), 64u);
    ASSERT_EQ(three.uvs.size(), three.positions.size());
    for (std::size_t i = 0; i < three.positions.size(); ++i) {
        EXPECT_EQ(three.positions[i].z, 0.0f);
        EXPECT_EQ(three.uvs[i], glm::vec2(three.positions[i])) << "uvs interpolate as positions do here";
    }
    EXPECT_EQ(three.triangleMaterials, std::vector<int>(64, 3));
}

TEST(MeshDisplacement, ConstantTextureMovesAFlatQuadByScaleTimesValueAlongItsNormal) {
    const fs::path dir = scratch("constant");
    writeRow(dir / "grey.png", [](int) { return 128; });
    const Scene s = load(dir, quadScene(R"("displacement_texture": "grey.png", "displacement_scale": 0.5,
                                           "displacement_subdivision": 2)"));
    const Mesh& m = s.meshes.at(0);
    EXPECT_EQ(m.triangles.size(), 32u);
    EXPECT_EQ(m.displacement.trianglesBefore, 2u);
    const float expected = 0.5f * (128.0f / 255.0f);   // linear data: 8-bit 128 is 128/255
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(m.positions[i].z, expected, 1e-6f) << i;
        EXPECT_NEAR(m.positions[i].x, 2.0f * m.uvs[i].x - 1.0f, 1e-6f) << "moved along the normal only";
        EXPECT_NEAR(glm::distance(m.normals[i], glm::vec3(0, 0, 1)), 0.0f, 1e-6f) << i;
    }
    // A negative scale pushes the other way.
    const Scene in = load(dir, quadScene(R"("displacement_texture": "grey.png", "displacement_scale": -2)"));
    for (const glm::vec3& p : in.meshes.at(0).positions) EXPECT_NEAR(p.z, -2.0f * 128.0f / 255.0f, 1e-6f);
    fs::remove_all(dir);
}

TEST(MeshDisplacement, RampTextureGivesBilinearHeightsAndTiltedNormals) {
    // Red 32 i in texel i: bilinear between texel centres, the vertex at u = k / 8 (k = 1..7) lies
    // halfway between texels k − 1 and k: height (32k − 16) / 255. Inside the ramp the surface is the
    // plane z = s (u − 1/16) 256/255 with u = (x + 1) / 2: normal ∝ (−s 128/255, 0, 1).
    const fs::path dir = scratch("ramp");
    writeRow(dir / "ramp.png", [](int i) { return 32 * i; });
    const float s = 0.25f;
    const Scene scene = load(dir, quadScene(R"("displacement_texture": "ramp.png", "displacement_scale": 0.25,
                                               "displacement_subdivision": 3)"));
    const Mesh& m = scene.meshes.at(0);
    const glm::vec3 tilted = glm::normalize(glm::vec3(-s * 128.0f / 255.0f, 0.0f, 1.0f));
    int checked = 0, normals = 0;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const float k = m.uvs[i].x * 8.0f;
        if (k < 0.5f || k > 7.5f) continue;   // u = 0 and 1 blend with the wrapped texel
        EXPECT_NEAR(m.positions[i].z, s * (32.0f * std::round(k) - 16.0f) / 255.0f, 1e-6f) << "u " << m.uvs[i].x;
        ++checked;
        if (k > 1.5f && k < 6.5f) {   // every triangle around it lies in the ramp's plane
            EXPECT_NEAR(glm::distance(m.normals[i], tilted), 0.0f, 1e-5f) << "u " << m.uvs[i].x;
            ++normals;
        }
    }
    EXPECT_EQ(checked, 7 * 9);
    EXPECT_EQ(normals, 5 * 9);
    fs::remove_all(dir);
}

TEST(MeshDisplacement, NormalsOfADisplacedSphereAreRadialAndKeepTheirSide) {
    // A subdivided octahedron pushed onto the unit sphere, with radial normals, displaced by 0.5
    // everywhere: radius 1.5, and the recomputed normals point outwards, close to radial.
    Mesh m = subdivideMesh(octahedron(), 4);
    for (std::size_t i = 0; i < m.positions.size(); ++i) m.positions[i] = m.normals[i] = glm::normalize(m.positions[i]);
    displaceAlongNormals(m, [](std::size_t) { return 0.5f; });
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(m.positions[i]), 1.5f, 1e-5f) << i;
        EXPECT_GT(glm::dot(m.normals[i], glm::normalize(m.positions[i])), 0.995f) << i;
    }
    // The same with the triangles wound the other way: the normals stay outwards.
    for (glm::uvec3& t : m.triangles) std::swap(t.y, t.z);
    displaceAlongNormals(m, [](std::size_t) { return 0.0f; });
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        EXPECT_GT(glm::dot(m.normals[i], glm::normalize(m.positions[i])), 0.995f) << i;
}

TEST(MeshDisplacement, TheBvhHoldsTheDisplacedSurface) {
    // Rays straight down −z onto the quad displaced by a constant: they hit at z = scale × value.
    const fs::path dir = scratch("bvh");
    writeRow(dir / "white.png", [](int) { return 255; });
    const Scene s = load(dir, quadScene(R"("displacement_texture": "white.png", "displacement_scale": 0.3,
                                           "displacement_subdivision": 3)"));
    const SceneGeometry g = buildSceneGeometry(s);
    EXPECT_EQ(g.triangleCount(), 128u);
    glsl::cpuTraversal = {&g, 0, 0};
    for (const glm::vec2 xy : {glm::vec2(0.1f, 0.2f), glm::vec2(-0.7f, 0.55f), glm::vec2(0.9f, -0.9f)}) {
        glsl::TraceRecord rec{};
        ASSERT_TRUE(glsl::traceScene(glsl::Ray(glm::vec3(xy, 5.0f), glm::vec3(0, 0, -1)), glsl::FLOAT_MAX, false, rec));
        EXPECT_NEAR(rec.t, 5.0f - 0.3f, 1e-5f);
    }
    fs::remove_all(dir);
}

TEST(MeshDisplacement, WriterKeepsTheInlineMeshAsGivenAndItsKeys) {
    const fs::path dir = scratch("writer");
    writeRow(dir / "ramp.png", [](int i) { return 32 * i; });
    const Scene s = load(dir, quadScene(R"("displacement_texture": "ramp.png", "displacement_scale": 0.25,
                                           "displacement_subdivision": 2, "transform": { "translation": [0, 1, 0] })"));
    const nlohmann::json j = sceneToJson(s, dir / "saved.json");
    const nlohmann::json& o = j["objects"][0];
    EXPECT_EQ(o["positions"].size(), 12u) << "the four vertices as given, not the displaced 25";
    EXPECT_EQ(o["displacement_texture"], "ramp.png");
    EXPECT_EQ(o["displacement_scale"], 0.25);
    EXPECT_EQ(o["displacement_subdivision"], 2);
    EXPECT_EQ(o["transform"]["translation"], nlohmann::json::array({0, 1, 0}));
    std::ofstream(dir / "saved.json") << j.dump(2);
    const Scene again = loadScene(dir / "saved.json");
    EXPECT_EQ(again.meshes.at(0).positions, s.meshes.at(0).positions) << "loading displaces it the same way again";
    EXPECT_EQ(again.meshes.at(0).normals, s.meshes.at(0).normals);
    fs::remove_all(dir);
}

TEST(MeshDisplacement, SceneStatsReportTheTrianglesBeforeAndAfter) {
    const fs::path dir = scratch("stats");
    writeRow(dir / "grey.png", [](int) { return 128; });
    const Scene s = load(dir, quadScene(R"("displacement_texture": "grey.png", "displacement_subdivision": 3)"));
    const SceneStats st = sceneStats(s, buildSceneGeometry(s));
    EXPECT_EQ(st.displacedMeshes, 1u);
    EXPECT_EQ(st.displacedTrianglesBefore, 2u);
    EXPECT_EQ(st.displacedTriangles, 128u);
    EXPECT_EQ(st.triangles, 128u);
    EXPECT_GE(st.displacementMs, 0.0);
    const std::string text = describeSceneStats(st);
    EXPECT_NE(text.find("scene: displacement: 1 meshes, 2 -> 128 triangles, "), std::string::npos) << text;
    const Scene plain = load(dir, quadScene(R"("normals": [0,0,1, 0,0,1, 0,0,1, 0,0,1])"));
    EXPECT_EQ(describeSceneStats(sceneStats(plain, buildSceneGeometry(plain))).find("displacement"), std::string::npos)
        << "no displacement line without displacement";
    fs::remove_all(dir);
}

TEST(MeshDisplacement, LiveKeysDisplaceAgainFromTheShapeAsGivenAsLoadingWould) {
    const fs::path dir = scratch("live");
    writeRow(dir / "ramp.png", [](int i) { return 32 * i; });
    writeRow(dir / "grey.png", [](int) { return 128; });
    Scene s = load(dir, quadScene(R"("displacement_texture": "ramp.png", "displacement_scale": 0.25,
                                     "displacement_subdivision": 2)"));
    EXPECT_EQ(setParam(s, "objects.0.displacement_subdivision", "3"), Trigger::ReloadScene);
    setParam(s, "objects.0.displacement_scale", "-0.5");
    setParam(s, "objects.0.displacement_texture", "grey.png");
    const Scene loaded = load(dir, quadScene(R"("displacement_texture": "grey.png", "displacement_scale": -0.5,
                                                "displacement_subdivision": 3)"));
    const Mesh& m = s.meshes.at(0);
    EXPECT_EQ(m.triangles.size(), 128u);
    EXPECT_EQ(m.displacement.trianglesBefore, 2u) << "from the two triangles as given, not the 32 displaced ones";
    EXPECT_EQ(m.positions, loaded.meshes.at(0).positions);
    EXPECT_EQ(m.normals, loaded.meshes.at(0).normals);
    EXPECT_EQ(sceneToJson(s), sceneToJson(loaded));
    fs::remove_all(dir);
}

TEST(MeshDisplacement, LiveKeysKeepEachTrianglesMaterial) {
    const fs::path dir = scratch("live_materials");
    writeRow(dir / "grey.png", [](int) { return 128; });
    Scene s = load(dir, quadScene(R"("displacement_texture": "grey.png", "displacement_subdivision": 1)"));
    // As a glTF file's per-triangle materials: the first given triangle's 4 children use 7, the second's 9.
    s.meshes.at(0).triangleMaterials = {7, 7, 7, 7, 9, 9, 9, 9};
    setParam(s, "objects.0.displacement_subdivision", "2");
    std::vector<int> expected(32, 7);   // 2 x 4^2 triangles, 16 from each given one
    std::fill(expected.begin() + 16, expected.end(), 9);
    EXPECT_EQ(s.meshes.at(0).triangleMaterials, expected);
    fs::remove_all(dir);
}

TEST(MeshDisplacement, BadLiveValuesAreLocatedErrorsAndLeaveTheMesh) {
    const fs::path dir = scratch("live_errors");
    writeRow(dir / "grey.png", [](int) { return 128; });
    Scene s = load(dir, quadScene(R"("displacement_texture": "grey.png", "displacement_subdivision": 1)"));
    const nlohmann::json before = sceneToJson(s);
    const std::vector<glm::vec3> positions = s.meshes.at(0).positions;
    auto error = [&](const std::string& key, const std::string& value) {
        try {
            setParam(s, key, value);
        } catch (const EditError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("objects.0.displacement_subdivision", "9"), "objects.0.displacement_subdivision: must be in [0, 8], got 9");
    EXPECT_EQ(error("objects.0.displacement_scale", "\"high\""), "objects.0.displacement_scale: expected a number, got \"high\"");
    EXPECT_EQ(error("objects.0.displacement_texture", "missing.png"),
              "objects[0].displacement_texture: " + (dir / "missing.png").string() + ": cannot read: no such file");
    EXPECT_EQ(error("objects.0.displacement_texture", "\"\""),
              "objects[0].displacement_texture: expected the path of an image file (a string), got empty string");
    EXPECT_EQ(sceneToJson(s), before);
    EXPECT_EQ(s.meshes.at(0).positions, positions);
    // A mesh without uvs cannot take a texture, as on loading.
    Scene flat = parseScene(R"({ "objects": [ { "type": "mesh", "positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0,1,2] } ] })",
                            (dir / "flat.json").string());
    std::swap(s, flat);
    EXPECT_EQ(error("objects.0.displacement_texture", "grey.png"),
              "objects[0].displacement_texture: the mesh has no uvs to read the displacement texture at");
    EXPECT_EQ(error("objects.0.radius", "2"),
              "objects.0.radius: meshes have no key 'radius' (keys: transform.translation, transform.rotation, "
              "transform.scale, material, displacement_texture, displacement_scale, displacement_subdivision)");
    fs::remove_all(dir);
}
