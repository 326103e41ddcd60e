// Mesh instances in the panels, drawn in ImGui frames without a window: the box overlay draws
// the meshes' boxes (the Cornell box has no spheres), and the Material panel shows a selected mesh
// without changing the scene.
#include "app/scene_object.h"

#include "support/panel_frame_test.h"

#include <imgui_internal.h>

namespace raylab::ui {
namespace {

class MeshPanelsTest : public test::PanelFrameTest {
protected:
    void SetUp() override {
        PanelFrameTest::SetUp();
        ASSERT_TRUE(viewer->openScene(test::scenePath("cornell_box.json"))) << viewer->document().lastError();
        ASSERT_TRUE(viewer->document().set("render.width", "24"));
        ASSERT_TRUE(viewer->document().set("render.height", "24"));
    }
    int viewportVertices() {
        frame();
        const ImGuiWindow* w = ImGui::FindWindowByName("Viewport");
        return w ? w->DrawList->VtxBuffer.Size : 0;
    }
};

TEST_F(MeshPanelsTest, TheBoxOverlayDrawsMeshInstances) {
    ASSERT_TRUE(viewer->scene().spheres.empty());
    for (int i = 0; i < 2; ++i) frame();
    const int without = viewportVertices();
    viewer->overlays.boxes = true;
    const int all = viewportVertices();
    // 8 meshes × 12 edges, 4 vertices a line (clipped ones may be left out, not many).
    EXPECT_GT(all - without, 4 * 12 * 4);
    viewer->overlays.boxes = false;
    viewer->overlays.selectedOnly = true;
    viewer->selection.select(objectCount(viewer->scene()) - 1);
    const int selected = viewportVertices();
    EXPECT_GT(selected, without);
    EXPECT_LT(selected, all);
}

TEST_F(MeshPanelsTest, TheMaterialPanelShowsASelectedMeshWithoutChangingIt) {
    const nlohmann::json before = sceneToJson(viewer->scene());
    viewer->selection.select(3);
    for (int i = 0; i < 3; ++i) frame();
    EXPECT_EQ(sceneToJson(viewer->scene()), before);
    EXPECT_EQ(viewer->selection.object(), 3);
    EXPECT_NE(ImGui::FindWindowByName("Material"), nullptr);
}

} // namespace
} // namespace raylab::ui
