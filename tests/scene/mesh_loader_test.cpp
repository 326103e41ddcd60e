// Meshes and transforms in scene files: inline arrays, OBJ files (relative to the scene), errors
// that name the place (and the OBJ file), and the round trip through sceneToJson.
#include "scene/obj_loader.h"
#include "scene/scene_loader.h"
#include "scene/transform.h"

#include "support/scene_errors.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

std::string errorOf(const std::string& text, const std::string& file = "test.json") {
    return test::sceneErrorOf(text, {}, file);
}

constexpr const char* kQuad = R"({ "materials": { "m": { "albedo": 0.5 } }, "objects": [
  { "type": "mesh", "material": "m",
    "positions": [0, 0, 0,  1, 0, 0,  1, 1, 0,  0, 1, 0],
    "indices": [0, 1, 2,  0, 2, 3],
    "normals": [0, 0, 2,  0, 0, 1,  0, 0, 1,  0, 0, 1],
    "uvs": [0, 0,  1, 0,  1, 1,  0, 1],
    "transform": { "translation": [1, 2, 3], "rotation": [0, 90, 0], "scale": 2 } } ] })";

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_mesh_test_" + name + std::to_string(::getpid()));
    fs::create_directories(dir / "models");
    return dir;
}

} // namespace

TEST(MeshLoader, InlineMeshWithNormalsUvsAndTransform) {
    const Scene s = parseScene(kQuad, "quad.json");
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_TRUE(s.spheres.empty());
    const Mesh& m = s.meshes[0];
    EXPECT_EQ(m.positions.size(), 4u);
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
    EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1)) << "normals are normalised";
    EXPECT_EQ(m.uvs[2], glm::vec2(1, 1));
    EXPECT_EQ(s.materials[size_t(m.material)].name, "m");
    EXPECT_EQ(m.transform.scale, glm::vec3(2.0f)) << "one number scales all axes";
    // world = T · R · S: the local x axis, scaled by 2, turned 90° about y, goes to -z.
    const glm::vec3 p = glm::vec3(transformMatrix(m.transform) * glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(p.x, 1.0f, 1e-6f);
    EXPECT_NEAR(p.y, 2.0f, 1e-6f);
    EXPECT_NEAR(p.z, 1.0f, 1e-6f);
    const glm::mat4 both = inverseTransformMatrix(m.transform) * transformMatrix(m.transform);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(both[c][r], c == r ? 1.0f : 0.0f, 1e-6f);
}

TEST(MeshLoader, SphereTransformsMoveTheCentreAndScaleTheRadius) {
    const Scene s = parseScene(R"({ "objects": [ { "type": "sphere", "center": [1, 0, 0], "radius": 0.5,
        "transform": { "translation": [0, 0, 5], "rotation": [0, 0, 90], "scale": [3, 3, 3] } } ] })", "s.json");
    const Sphere w = worldSphere(s.spheres.at(0));
    EXPECT_NEAR(w.center.x, 0.0f, 1e-6f);
    EXPECT_NEAR(w.center.y, 3.0f, 1e-6f);
    EXPECT_NEAR(w.center.z, 5.0f, 1e-6f);
    EXPECT_FLOAT_EQ(w.radius, 1.5f);
}

TEST(MeshLoader, ErrorsNameTheValue) {
    auto mesh = [](const std::string& members) {
        return std::string(R"({ "objects": [ { "type": "mesh", )") + members + " } ] }";
    };
    EXPECT_EQ(errorOf(mesh(R"("positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0, 1, 3])")),
              "test.json:1:88: error: objects[0].indices[2]: vertex index 3 is out of range (3 vertices)");
    EXPECT_EQ(errorOf(mesh(R"("positions": [0,0,0, 1,0], "indices": [0, 1, 2])")),
              "test.json:1:47: error: objects[0].positions: expected a multiple of 3 numbers, got 5");
    EXPECT_EQ(errorOf(mesh(R"("positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0, 1, -2])")),
              "test.json:1:88: error: objects[0].indices[2]: must be in [0, 4294967295], got -2");
    EXPECT_EQ(errorOf(mesh(R"("indices": [0, 1, 2])")),
              "test.json:1:16: error: objects[0]: a mesh needs \"positions\" (or \"file\" with an OBJ path)");
    // A name too long for the file system is a missing file, not a raw filesystem_error (a fuzzer's find).
    EXPECT_NE(errorOf(mesh(R"("file": ")" + std::string(5000, 'x') + R"(.obj")")).find("cannot read: no such file"),
              std::string::npos);
    EXPECT_EQ(errorOf(mesh(R"("file": "a.obj", "positions": [0,0,0])")),
              "test.json:1:51: error: objects[0].positions: a mesh takes either \"file\" or inline arrays, not both");
    EXPECT_EQ(errorOf(mesh(R"("positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0,1,2], "radius": 1)")),
              "test.json:1:90: error: objects[0].radius: unknown key 'radius' in objects[0] (known keys: type, "
              "material, transform, file, positions, indices, normals, uvs, emission_sides, displacement_texture, "
              "displacement_scale, displacement_subdivision)");
    EXPECT_EQ(errorOf(mesh(R"("positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0,1,2], "normals": [0,0,1])")),
              "test.json:1:101: error: objects[0].normals: expected one normal per vertex (9 numbers), got 3 numbers");
    EXPECT_EQ(errorOf(R"({ "objects": [ { "type": "sphere", "transform": { "scale": [1, 2, 1] } } ] })"),
              "test.json:1:60: error: objects[0].transform.scale: a sphere needs a uniform scale (one number or "
              "three equal ones), got [1, 2, 1]");
    EXPECT_EQ(errorOf(R"({ "objects": [ { "type": "sphere", "transform": { "scale": 0 } } ] })"),
              "test.json:1:60: error: objects[0].transform.scale: must be > 0, got 0");
    EXPECT_EQ(errorOf(R"({ "objects": [ { "transform": { "rotaton": [0, 0, 0] } } ] })"),
              "test.json:1:33: error: objects[0].transform.rotaton: unknown key 'rotaton' in objects[0].transform; "
              "did you mean 'rotation'?");
}

TEST(MeshLoader, ObjFilesRelativeToTheSceneWithMergedVertices) {
    const fs::path dir = scratch("obj");
    std::ofstream(dir / "models" / "quad.obj") << "# a quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                                  "vn 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                                  "f 1/1/1 2/2/1 3/3/1 4/4/1\n";
    std::ofstream(dir / "scene.json") << R"({ "objects": [ { "type": "mesh", "file": "models/quad.obj",
        "transform": { "translation": [0, 1, 0] } } ] })";
    const Scene s = loadScene(dir / "scene.json");
    ASSERT_EQ(s.meshes.size(), 1u);
    const Mesh& m = s.meshes[0];
    EXPECT_EQ(m.file, "models/quad.obj");
    EXPECT_EQ(m.positions.size(), 4u) << "shared corners are merged";
    EXPECT_EQ(m.triangles.size(), 2u) << "the quad is triangulated";
    EXPECT_EQ(m.normals.size(), 4u);
    EXPECT_EQ(m.uvs.size(), 4u);
    for (std::size_t v = 0; v < m.positions.size(); ++v)
        EXPECT_EQ(m.uvs[v], glm::vec2(m.positions[v])) << "each corner keeps its own uv";
    // Round trip keeps the file reference.
    const nlohmann::json j = sceneToJson(s);
    EXPECT_EQ(j["objects"][0]["file"], "models/quad.obj");
    std::ofstream(dir / "again.json") << j.dump(2);
    EXPECT_EQ(loadScene(dir / "again.json").meshes.at(0).positions.size(), 4u);
}

TEST(MeshLoader, ObjErrorsNameTheSceneAndTheObjFile) {
    const fs::path dir = scratch("objerr");
    std::ofstream(dir / "scene.json") << R"({ "objects": [ { "type": "mesh", "file": "models/none.obj" } ] })";
    const std::string missing = [&] {
        try {
            loadScene(dir / "scene.json");
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("<no error>");
    }();
    EXPECT_EQ(missing, (dir / "scene.json").string() + ":1:42: error: objects[0].file: " +
                           (dir / "models" / "none.obj").string() + ": cannot read: no such file");
    std::ofstream(dir / "models" / "bad.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
    std::ofstream(dir / "bad.json") << R"({ "objects": [ { "type": "mesh", "file": "models/bad.obj" } ] })";
    try {
        loadScene(dir / "bad.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("bad.json:1:42: error: objects[0].file: "), std::string::npos) << msg;
        EXPECT_NE(msg.find("models/bad.obj"), std::string::npos) << msg;
    }
}

TEST(MeshLoader, InlineMeshesAndTransformsRoundTrip) {
    const Scene s = parseScene(kQuad, "quad.json");
    const Scene again = parseScene(sceneToJson(s).dump(), "again.json");
    ASSERT_EQ(again.meshes.size(), 1u);
    EXPECT_EQ(again.meshes[0].positions, s.meshes[0].positions);
    EXPECT_EQ(again.meshes[0].triangles, s.meshes[0].triangles);
    EXPECT_EQ(again.meshes[0].normals, s.meshes[0].normals);
    EXPECT_EQ(again.meshes[0].uvs, s.meshes[0].uvs);
    EXPECT_EQ(again.meshes[0].transform, s.meshes[0].transform);
    EXPECT_EQ(again.materials[size_t(again.meshes[0].material)].name, "m");
}

namespace {

// What loadObj says about an OBJ text, or "<no error>".
std::string objErrorOf(const std::string& text) {
    const fs::path file = scratch("objtext") / "m.obj";
    std::ofstream(file, std::ios::binary) << text;
    try {
        loadObj(file);
    } catch (const ObjError& e) {
        const std::string msg = e.what();
        return msg.rfind(file.string(), 0) == 0 ? msg.substr(file.string().size()) : "(file not named) " + msg;
    }
    return "<no error>";
}

} // namespace

TEST(MeshLoader, ObjProblemsNameTheLineAndWhatIsWrong) {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_EQ(objErrorOf(tri + "vn 0 0 1\nf 1//1 2//1 3//2\n"),
              ":5: face vertex '3//2': normal index 2 is out of range (1 normals)");
    EXPECT_EQ(objErrorOf(tri + "vt 0 0\nf 1/1 2/1 3/3\n"),
              ":5: face vertex '3/3': texture coordinate index 3 is out of range (1 texture coordinates)");
    EXPECT_EQ(objErrorOf(tri + "f 1 2\n"), ":4: a face needs at least 3 vertices, got 2");
    EXPECT_EQ(objErrorOf(tri + "f 1 2 4\n"), ":4: face vertex '4': position index 4 is out of range (3 positions)");
    EXPECT_EQ(objErrorOf("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"),
              ":2: a vertex position: 'nan' is not a finite 32-bit float");
    EXPECT_EQ(objErrorOf("v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n"), ":2: a vertex position: 'zero' is not a number");
    EXPECT_EQ(objErrorOf(tri + "f 1 2 3\nf 3 2 1/"), ":5: face vertex '1/' is incomplete (expected v, v/vt, v//vn or v/vt/vn)");
    EXPECT_EQ(objErrorOf(tri + "f -1 -2 -4\n"), ":4: face vertex '-4': position index -4 is out of range (3 positions so far)");
}

TEST(MeshLoader, ObjMaterialsGroupsAndCommentsAreIgnored) {
    const Mesh m = [] {
        const fs::path file = scratch("objok") / "m.obj";
        std::ofstream(file) << "mtllib missing.mtl\no thing\ng\nusemtl red\nv 0 0 0 # origin\nv 1 0 0\n"
                               "v 0 1 0\nv 1 1 0\r\nvt 0.5\nf 1/1 2/1 3/1\ns off\nf -3/1 -2/1 -1/1\nl 1 2\n";
        return loadObj(file);
    }();
    EXPECT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.uvs.size(), 4u);
}
