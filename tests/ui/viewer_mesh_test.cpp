// Mesh instances in the viewer's model on a headless context: a click on the Cornell box's wall
// selects that mesh and its material (also for the BRDF explorer), a material edit changes the
// image without compiling, a transform edit (or a reload that only moves objects) keeps the
// meshes' BVHs and moves the object in the image, and the object-id view tells apart objects
// that share a material.
#include "app/scene_object.h"
#include "app/view_geometry.h"
#include "app/viewer.h"

#include "render/render_helpers.h"
#include "support/viewer_test_base.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace raylab::ui {
namespace {

constexpr int kSize = 64;   // the Cornell box traced at 64 × 64

class ViewerMeshTest : public test::ViewerTestBase {
protected:
    void SetUp() override {
        ViewerTestBase::SetUp();
        openSmall("cornell_box.json", kSize, kSize);
        ASSERT_TRUE(viewer->document().set("render.spp", "2"));
    }
    void traceToTarget() {
        for (int i = 0; i < 100000 && !viewer->converged(); ++i) viewer->update(1e-3);
        ASSERT_TRUE(viewer->converged());
    }
    Image traced() {
        traceToTarget();
        return viewer->tracer()->readImage();
    }
    int materialNamed(const std::string& name) const {
        const Scene& s = viewer->scene();
        for (std::size_t i = 0; i < s.materials.size(); ++i)
            if (s.materials[i].name == name) return int(i);
        return -1;
    }
    // The object made of `material` (the Cornell box's walls each have their own, but for white).
    int objectOf(const std::string& material) const {
        for (int i = 0; i < objectCount(viewer->scene()); ++i)
            if (objectMaterial(viewer->scene(), i) == materialNamed(material)) return i;
        return -1;
    }
    // Where the world point lands in the traced image (the tracer's camera maths).
    ImagePoint at(glm::vec3 p) const {
        const auto q = projectPoint(viewer->scene(), viewer->imageWidth(), viewer->imageHeight(), p);
        EXPECT_TRUE(q);
        return q.value_or(ImagePoint{});
    }
};

// On the green (right, x = 0) wall, and on the front face of the tall block (its corners
// (265, y, 296) and (423, y, 247) in cornell_box.json).
const glm::vec3 kGreenWall(0.0f, 274.0f, 400.0f);
const glm::vec3 kTallBlockFront(344.0f, 250.0f, 271.5f);

TEST_F(ViewerMeshTest, ClickingTheWallSelectsThatMeshAndItsMaterialEverywhere) {
    const int wall = objectOf("green");
    ASSERT_GE(wall, 0);
    ASSERT_TRUE(objectRef(viewer->scene(), wall)->mesh);
    const ImagePoint p = at(kGreenWall);
    EXPECT_EQ(viewer->pick(p.x, p.y), wall);
    EXPECT_EQ(viewer->selection.object(), wall);
    EXPECT_EQ(viewer->selection.editedMaterial(), materialNamed("green"));
    EXPECT_EQ(viewer->brdfExplorer.resolvedMaterial(*viewer), materialNamed("green"))
        << "the BRDF explorer's 'selected material' is the mesh's";
    ASSERT_FALSE(log.entries().empty());
    EXPECT_NE(log.entries().front().text.find("picked object " + std::to_string(wall) + " (material green), mesh"),
              std::string::npos)
        << log.entries().front().text;
    // The tall block, also a mesh, made of white (shared with the floor, ceiling, back wall).
    const ImagePoint b = at(kTallBlockFront);
    const auto block = viewer->pick(b.x, b.y);
    ASSERT_TRUE(block);
    EXPECT_EQ(*block, int(viewer->scene().meshes.size()) - 1) << "the tall block is the last object";
    EXPECT_EQ(viewer->brdfExplorer.resolvedMaterial(*viewer), materialNamed("white"));
}

TEST_F(ViewerMeshTest, AMeshMaterialEditChangesTheImageAndCompilesNothing) {
    const Image before = traced();
    const ImagePoint p = at(kGreenWall);
    ASSERT_TRUE(viewer->pick(p.x, p.y));
    const std::string variant = viewer->shaderVariant();
    const std::size_t compiled = viewer->tracer()->compiledVariants();
    const double compileSeconds = viewer->stats().shaderCompileSeconds;
    const std::uint64_t restarts = viewer->stats().restarts;
    const auto& gpu = viewer->tracer()->gpuScene();
    const std::uint64_t builds = gpu.meshBvhBuilds(), materialUpdates = gpu.materialUpdates();
    // As the script's `set selected.albedo` does (selectedKey: the edited material's key).
    ASSERT_TRUE(viewer->document().set("materials." + std::to_string(viewer->selection.editedMaterial()) + ".albedo", "[0.9, 0.9, 0.1]"));
    EXPECT_EQ(viewer->stats().restarts, restarts + 1) << "accumulation restarts";
    EXPECT_EQ(gpu.meshBvhBuilds(), builds) << "a material edit keeps the meshes' BVHs";
    EXPECT_EQ(gpu.materialUpdates(), materialUpdates + 1) << "the materials alone were uploaded";
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 0u);
    const Image after = traced();
    EXPECT_EQ(viewer->shaderVariant(), variant);
    EXPECT_EQ(viewer->tracer()->compiledVariants(), compiled) << "same features: no compile";
    EXPECT_EQ(viewer->stats().shaderCompileSeconds, compileSeconds);
    // The wall went from green to yellow: red grows where it is seen.
    const int x = int(p.x), y = kSize - 1 - int(p.y);   // readImage's rows start at the bottom
    EXPECT_GT(after.rgb(x, y).r, before.rgb(x, y).r * 2.0f) << "before " << before.rgb(x, y).r;
    // A change of the feature set does compile (the counter can tell): f0 turns on the GGX code.
    ASSERT_TRUE(viewer->document().set("materials." + std::to_string(viewer->selection.editedMaterial()) + ".f0", "0.5"));
    EXPECT_EQ(viewer->tracer()->compiledVariants(), compiled + 1);
    EXPECT_NE(viewer->shaderVariant(), variant);
}

TEST_F(ViewerMeshTest, MovingAMeshPlacesItsBakedTrianglesAgainAndTheObjectMovesInTheImage) {
    viewer->setDebugView(DebugView::ObjectId);
    ASSERT_EQ(viewer->debugView(), DebugView::ObjectId) << viewer->document().lastError();
    const int block = int(viewer->scene().meshes.size()) - 1;   // the tall block
    const ImagePoint oldAt = at(kTallBlockFront);
    const glm::vec3 shift(-200.0f, 0.0f, 0.0f);
    const ImagePoint newAt = at(kTallBlockFront + shift);
    ASSERT_EQ(pickObject(viewer->scene(), *viewer->geometry(), kSize, kSize, oldAt), block);
    ASSERT_NE(pickObject(viewer->scene(), *viewer->geometry(), kSize, kSize, newAt), block);
    const Image before = traced();
    const auto& gpu = viewer->tracer()->gpuScene();
    const std::uint64_t builds = gpu.meshBvhBuilds(), updates = gpu.topLevelUpdates();
    const std::size_t compiled = viewer->tracer()->compiledVariants();
    ASSERT_TRUE(viewer->document().set("objects." + std::to_string(block) + ".transform.translation", "[-200, 0, 0]"));
    // The box's small meshes have their transforms baked into their vertices
    // (render/baked_mesh_transforms.h): a move places their few triangles again, keeps the
    // meshes-in-world variant and compiles nothing.
    EXPECT_EQ(gpu.meshBvhBuilds(), builds + 1) << "the baked triangles are placed again";
    EXPECT_EQ(gpu.topLevelUpdates(), updates + 1);
    EXPECT_EQ(viewer->tracer()->compiledVariants(), compiled) << "the same features: no compile";
    EXPECT_NE(viewer->shaderVariant().find("meshes-in-world"), std::string::npos) << viewer->shaderVariant();
    ASSERT_TRUE(viewer->document().set("objects." + std::to_string(block) + ".transform.translation", "[-201, 0, 0]"));
    ASSERT_TRUE(viewer->document().set("objects." + std::to_string(block) + ".transform.translation", "[-200, 0, 0]"));
    EXPECT_EQ(gpu.meshBvhBuilds(), builds + 3);
    EXPECT_EQ(gpu.topLevelUpdates(), updates + 3);
    EXPECT_EQ(viewer->tracer()->compiledVariants(), compiled) << "the same features: no compile";
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 0u);
    EXPECT_EQ(viewer->scene().meshes.back().transform.translation, shift);
    // The CPU copy the picking uses moved too.
    EXPECT_EQ(pickObject(viewer->scene(), *viewer->geometry(), kSize, kSize, newAt), block);
    EXPECT_NE(pickObject(viewer->scene(), *viewer->geometry(), kSize, kSize, oldAt), block);
    // In the traced object-id view the block's colour left the old place and shows at the new one.
    const Image after = traced();
    auto colour = [](const Image& im, ImagePoint p) { return im.rgb(int(p.x), kSize - 1 - int(p.y)); };
    const glm::vec3 blockColour = colour(before, oldAt);
    EXPECT_GT(glm::length(colour(after, oldAt) - blockColour), 0.05f);
    EXPECT_LT(glm::length(colour(after, newAt) - blockColour), 1e-5f);
    EXPECT_GT(glm::length(colour(before, newAt) - blockColour), 0.05f);
}

TEST_F(ViewerMeshTest, ACameraEditUploadsNoSceneBuffers) {
    // A camera drag sets camera keys every frame: none of them may rebuild a BVH or upload materials.
    const auto& gpu = viewer->tracer()->gpuScene();
    const std::uint64_t builds = gpu.meshBvhBuilds(), updates = gpu.topLevelUpdates(),
                        materialUpdates = gpu.materialUpdates();
    const Image before = traced();
    ASSERT_TRUE(viewer->document().set("camera.fov", "30"));
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 0u) << "accumulation restarts";
    EXPECT_EQ(gpu.meshBvhBuilds(), builds);
    EXPECT_EQ(gpu.topLevelUpdates(), updates);
    EXPECT_EQ(gpu.materialUpdates(), materialUpdates);
    const Image after = traced();
    float change = 0.0f;
    for (std::size_t i = 0; i < before.rgba.size(); ++i) change += std::abs(after.rgba[i] - before.rgba[i]);
    EXPECT_GT(change / float(before.rgba.size()), 0.01f) << "the narrower view shows";
}

TEST_F(ViewerMeshTest, AReloadThatOnlyMovesAMeshIsATransformUpdate) {
    const auto file = std::filesystem::temp_directory_path() / "raylab_viewer_mesh_reload.json";
    Scene s = viewer->scene();
    std::ofstream(file) << sceneToJson(s).dump();
    ASSERT_TRUE(viewer->openScene(file)) << viewer->document().lastError();
    const auto& gpu = viewer->tracer()->gpuScene();
    const std::uint64_t builds = gpu.meshBvhBuilds(), updates = gpu.topLevelUpdates();
    s.meshes.back().transform.translation = glm::vec3(-50.0f, 0.0f, 0.0f);
    std::ofstream(file) << sceneToJson(s).dump();
    ASSERT_TRUE(viewer->openScene(file)) << viewer->document().lastError();
    // The box's small meshes are baked (render/baked_mesh_transforms.h): a move places their few
    // triangles again through the transform update, not a full upload.
    EXPECT_EQ(gpu.topLevelUpdates(), updates + 1) << "a move: a transform update";
    EXPECT_EQ(gpu.meshBvhBuilds(), builds + 1) << "the baked small meshes placed again";
    EXPECT_EQ(viewer->scene().meshes.back().transform.translation, glm::vec3(-50.0f, 0.0f, 0.0f));
    s.materials[0].albedo = glm::vec3(0.2f);
    std::ofstream(file) << sceneToJson(s).dump();
    ASSERT_TRUE(viewer->openScene(file)) << viewer->document().lastError();
    EXPECT_EQ(gpu.meshBvhBuilds(), builds + 2) << "a material changed: a full reload";
    EXPECT_EQ(gpu.topLevelUpdates(), updates + 1) << "a full upload, not a transform update";
    std::filesystem::remove(file);
}

TEST_F(ViewerMeshTest, ObjectIdsDifferWhereObjectsShareAMaterial) {
    // The floor (object 0) and the back wall (object 2) are both white.
    ASSERT_EQ(objectMaterial(viewer->scene(), 0), objectMaterial(viewer->scene(), 2));
    const ImagePoint floor = at(glm::vec3(430.0f, 0.0f, 100.0f)), back = at(glm::vec3(150.0f, 450.0f, 559.2f));
    ASSERT_EQ(pickObject(viewer->scene(), *viewer->geometry(), kSize, kSize, floor), 0);
    ASSERT_EQ(pickObject(viewer->scene(), *viewer->geometry(), kSize, kSize, back), 2);
    auto colour = [](const Image& im, ImagePoint p) { return im.rgb(int(p.x), kSize - 1 - int(p.y)); };
    viewer->setDebugView(DebugView::MaterialId);
    const Image materialId = traced();
    viewer->setDebugView(DebugView::ObjectId);
    EXPECT_EQ(viewer->tracer()->samplesPerPixel(), 0u) << "another quantity: restarted";
    const Image objectId = traced();
    EXPECT_LT(glm::length(colour(materialId, floor) - colour(materialId, back)), 1e-5f);
    EXPECT_GT(glm::length(colour(objectId, floor) - colour(objectId, back)), 0.05f);
    EXPECT_GT(test::rmse(materialId, objectId), 0.01);
}

TEST_F(ViewerMeshTest, ASphereAndAMeshOfOneMaterialGetDifferentObjectIds) {
    const auto file = std::filesystem::temp_directory_path() / "raylab_viewer_sphere_mesh.json";
    std::ofstream(file) << R"({"camera": {"position": [0, 0, 10], "look_at": [0, 0, 0], "fov": 40},
        "render": {"width": 40, "height": 20, "spp": 1}, "materials": {"white": {"albedo": 0.8}},
        "objects": [{"type": "sphere", "center": [-1.5, 0, 0], "radius": 1, "material": "white"},
                    {"type": "mesh", "material": "white", "positions": [1, -1, 0, 3, -1, 0, 3, 1, 0, 1, 1, 0],
                     "indices": [0, 1, 2, 0, 2, 3]}]})";
    ASSERT_TRUE(viewer->openScene(file)) << viewer->document().lastError();
    const ImagePoint sphere = at(glm::vec3(-1.5f, 0.0f, 1.0f)), quad = at(glm::vec3(2.0f, 0.0f, 0.0f));
    auto colour = [&](const Image& im, ImagePoint p) { return im.rgb(int(p.x), viewer->imageHeight() - 1 - int(p.y)); };
    viewer->setDebugView(DebugView::MaterialId);
    const Image materialId = traced();
    viewer->setDebugView(DebugView::ObjectId);
    const Image objectId = traced();
    EXPECT_LT(glm::length(colour(materialId, sphere) - colour(materialId, quad)), 1e-5f);
    EXPECT_GT(glm::length(colour(objectId, sphere) - colour(objectId, quad)), 0.05f);
    EXPECT_GT(glm::length(colour(objectId, sphere)), 0.2f) << "not the sky's black";
    EXPECT_GT(glm::length(colour(objectId, quad)), 0.2f);
    std::filesystem::remove(file);
}

} // namespace
} // namespace raylab::ui
