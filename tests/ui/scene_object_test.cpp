// The viewer's one numbering of objects (spheres, then mesh instances) without a window: picking
// through the tracer's BVH on the CPU finds meshes (and the nearest of a mesh and a sphere), edit
// keys reach mesh transforms, boxes bound meshes, and a reload that only moves objects says so.
#include "app/scene_change.h"
#include "scene/scene_keys.h"
#include "app/scene_object.h"
#include "app/view_geometry.h"

#include "scene/scene_loader.h"

#include <gtest/gtest.h>

namespace raylab::ui {
namespace {

Scene cornellBox() { return loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/cornell_box.json"); }

int materialNamed(const Scene& s, const std::string& name) {
    for (std::size_t i = 0; i < s.materials.size(); ++i)
        if (s.materials[i].name == name) return int(i);
    return -1;
}

// A sphere at the origin and, in front of it towards the camera, a quad mesh: both "white".
Scene quadBeforeSphere() {
    return parseScene(R"({"camera": {"position": [0, 0, 10], "look_at": [0, 0, 0], "fov": 40},
        "materials": {"white": {"albedo": 0.8}, "red": {"albedo": [0.8, 0.1, 0.1]}},
        "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white"},
                    {"type": "mesh", "material": "white", "positions": [-0.5, -0.5, 3, 0.5, -0.5, 3, 0.5, 0.5, 3, -0.5, 0.5, 3],
                     "indices": [0, 1, 2, 0, 2, 3]}]})",
                      "quad.json");
}

TEST(SceneObject, SpheresComeFirstThenMeshes) {
    const Scene s = quadBeforeSphere();
    ASSERT_EQ(objectCount(s), 2);
    EXPECT_FALSE(objectRef(s, 0)->mesh);
    EXPECT_TRUE(objectRef(s, 1)->mesh);
    EXPECT_EQ(objectRef(s, 1)->index, 0);
    EXPECT_FALSE(objectRef(s, 2));
    EXPECT_FALSE(objectRef(s, -1));
    EXPECT_EQ(objectLabel(s, 1), "1  mesh  white");
    EXPECT_EQ(objectLabel(s, 0), "0  sphere  white");
    // The order sceneToJson writes "objects" in.
    const nlohmann::json j = sceneToJson(s);
    EXPECT_EQ(j["objects"][0]["type"], "sphere");
    EXPECT_EQ(j["objects"][1]["type"], "mesh");
}

TEST(SceneObject, AMeshListsItsPerTriangleMaterialsInFirstUseOrder) {
    Scene s = quadBeforeSphere();
    const int white = materialNamed(s, "white"), red = materialNamed(s, "red");
    s.meshes[0].triangleMaterials = {red, -1};   // glTF: the second triangle keeps the mesh's own
    EXPECT_EQ(objectMaterials(s, 1), (std::vector<int>{red, white}));
    EXPECT_EQ(objectLabel(s, 1), "1  mesh  (2 materials)");
    s.meshes[0].triangleMaterials = {red, red};
    EXPECT_EQ(objectMaterials(s, 1), std::vector<int>{red}) << "the mesh's own material shows nowhere";
    EXPECT_EQ(objectMaterials(s, 0), std::vector<int>{white});
}

TEST(SceneObject, PickingTheCornellBoxesGreenWallSelectsThatMesh) {
    const Scene s = cornellBox();
    const SceneGeometry g = buildSceneGeometry(s);
    const int w = 64, h = 64;
    const int green = materialNamed(s, "green");
    int wall = -1;   // the mesh made of "green": the right wall at x = 0
    for (std::size_t j = 0; j < s.meshes.size(); ++j)
        if (s.meshes[j].material == green) wall = int(s.spheres.size() + j);
    ASSERT_GE(wall, 0);
    // A point on the wall (x = 0, inside 0..548.8 × 0..559.2), projected with the tracer's camera.
    const auto p = projectPoint(s, w, h, glm::vec3(0.0f, 274.0f, 400.0f));
    ASSERT_TRUE(p);
    const auto hit = viewHit(s, g, w, h, *p);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, wall);
    EXPECT_EQ(hit->material, green);
    EXPECT_NEAR(hit->position.x, 0.0f, 1e-2f);
    EXPECT_NEAR(hit->position.z, 400.0f, 0.5f);
    EXPECT_EQ(pickObject(s, g, w, h, *p), wall);
    EXPECT_EQ(pickObject(s, w, h, *p), wall) << "the overload that builds the geometry itself";
}

TEST(SceneObject, AMeshInFrontOfASphereIsPickedNotTheSphereBehindIt) {
    const Scene s = quadBeforeSphere();
    const SceneGeometry g = buildSceneGeometry(s);
    const auto centre = projectPoint(s, 200, 100, glm::vec3(0.0f));
    ASSERT_TRUE(centre);
    EXPECT_EQ(pickObject(s, g, 200, 100, *centre), 1);
    // Beside the quad (x 0.75 at z 0 is outside its shadow seen from the eye, inside the sphere).
    const auto side = projectPoint(s, 200, 100, glm::vec3(0.75f, 0.0f, 0.66f));
    ASSERT_TRUE(side);
    EXPECT_EQ(pickObject(s, g, 200, 100, *side), 0);
}

TEST(SceneObject, AMovedSpherePicksAndBoxesWhereItWent) {
    Scene s = quadBeforeSphere();
    s.spheres[0].transform.translation = glm::vec3(2.5f, 0.0f, 0.0f);
    s.spheres[0].transform.scale = glm::vec3(0.5f);
    const SceneGeometry g = buildSceneGeometry(s);
    const auto at = projectPoint(s, 200, 100, glm::vec3(2.5f, 0.0f, 0.0f));
    ASSERT_TRUE(at);
    EXPECT_EQ(pickObject(s, g, 200, 100, *at), 0);
    const Box b = objectBounds(s.spheres[0]);
    EXPECT_EQ(b.lo, glm::vec3(2.0f, -0.5f, -0.5f));
    EXPECT_EQ(b.hi, glm::vec3(3.0f, 0.5f, 0.5f));
}

TEST(SceneObject, AMeshsBoxIsItsWorldBounds) {
    Scene s = quadBeforeSphere();
    s.meshes[0].transform.translation = glm::vec3(1.0f, 2.0f, 0.0f);
    s.meshes[0].transform.rotation = glm::vec3(0.0f, 90.0f, 0.0f);   // the quad turns to face +x
    const SceneGeometry g = buildSceneGeometry(s);
    const auto b = objectBounds(s, g, 1);
    ASSERT_TRUE(b);
    // Object-space x -0.5..0.5, z 3 → after Ry(90°): x = z = 3, z = -x in -0.5..0.5; then moved.
    EXPECT_NEAR(b->lo.x, 4.0f, 1e-5f);
    EXPECT_NEAR(b->hi.x, 4.0f, 1e-5f);
    EXPECT_NEAR(b->lo.y, 1.5f, 1e-5f);
    EXPECT_NEAR(b->hi.y, 2.5f, 1e-5f);
    EXPECT_NEAR(b->lo.z, -0.5f, 1e-5f);
    EXPECT_NEAR(b->hi.z, 0.5f, 1e-5f);
    EXPECT_FALSE(objectBounds(s, g, 2));
}

TEST(SceneObject, EditKeysReachMeshTransformsAndMoveObjects) {
    Scene s = quadBeforeSphere();
    EXPECT_EQ(setParam(s, "objects.1.transform.translation", "[1, 2, 3]"), Trigger::MoveObjects);
    EXPECT_EQ(s.meshes[0].transform.translation, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(setParam(s, "objects.1.transform.scale", "[1, 2, 3]"), Trigger::MoveObjects);
    EXPECT_EQ(s.meshes[0].transform.scale, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(setParam(s, "objects.0.transform.translation", "[0, 1, 0]"), Trigger::MoveObjects);
    EXPECT_EQ(s.spheres[0].transform.translation, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(setParam(s, "objects.0.radius", "2"), Trigger::MoveObjects);
    const Scene before = s;
    EXPECT_THROW(setParam(s, "objects.0.transform.scale", "[1, 2, 1]"), EditError) << "a sphere stays a sphere";
    EXPECT_THROW(setParam(s, "objects.1.radius", "2"), EditError) << "meshes have no radius";
    EXPECT_THROW(setParam(s, "objects.2.transform.translation", "[0, 0, 0]"), EditError);
    EXPECT_EQ(sceneToJson(s), sceneToJson(before));
}

TEST(SceneChange, AReloadThatOnlyMovesObjectsKeepsTheMeshes) {
    const Scene a = quadBeforeSphere();
    EXPECT_EQ(reloadTrigger(a, a), Trigger::MoveObjects) << "nothing changed: nothing to rebuild either";
    Scene b = a;
    b.meshes[0].transform.translation.x = 3.0f;
    b.spheres[0].center.y = 1.0f;
    EXPECT_EQ(reloadTrigger(a, b), Trigger::MoveObjects);
    Scene c = b;
    c.materials[0].albedo = glm::vec3(0.1f);
    EXPECT_EQ(reloadTrigger(a, c), Trigger::ReloadScene) << "a material changed too";
    Scene d = b;
    d.meshes[0].positions[0].x = -0.6f;
    EXPECT_EQ(reloadTrigger(a, d), Trigger::ReloadScene) << "the mesh itself changed";
    Scene e = b;
    e.camera.fovY = 30.0f;
    EXPECT_EQ(reloadTrigger(a, e), Trigger::ReloadScene);
    Scene f = b;
    f.spheres.push_back(f.spheres[0]);
    EXPECT_EQ(reloadTrigger(a, f), Trigger::ReloadScene);
}

} // namespace
} // namespace raylab::ui
