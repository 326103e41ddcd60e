// The Inspector and BRDF explorer panels in ImGui frames without a window (as panels_test.cpp):
// they draw after an inspection and an "explore", the explorer computes its verdict, and drawing
// changes nothing in the scene.
#include "panels/panels.h"

#include "render/render_helpers.h"
#include "support/gl_test.h"
#include "support/panel_frame_test.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

namespace raylab::ui {
namespace {

class InspectorPanelsTest : public test::PanelFrameTest {};

TEST_F(InspectorPanelsTest, PanelsDrawAnInspectionAndTheExplorersVerdict) {
    frame();
    EXPECT_EQ(ImGui::FindWindowByName("Inspector"), nullptr) << "closed until asked for";
    ASSERT_TRUE(viewer->inspection.inspect(*viewer, 16, 12));
    const nlohmann::json before = sceneToJson(viewer->scene());
    const BounceRecord& first = viewer->inspection.paths().at(0).bounces.at(0);
    ASSERT_TRUE(first.hit);
    viewer->brdfExplorer.fromBounce(first);
    viewer->brdfExplorer.panelOpen = true;
    viewer->brdfExplorer.sampleCount = 4000;
    for (int i = 0; i < 3; ++i) frame();
    EXPECT_NE(ImGui::FindWindowByName("Inspector"), nullptr);
    EXPECT_NE(ImGui::FindWindowByName("BRDF explorer"), nullptr);
    EXPECT_EQ(viewer->brdfExplorer.resolvedMaterial(*viewer), first.material);
    ASSERT_TRUE(viewer->brdfExplorer.hasResults());
    EXPECT_EQ(viewer->brdfExplorer.test().samples, 4000);
    EXPECT_TRUE(viewer->brdfExplorer.test().pass) << viewer->brdfExplorer.test().chi2.pValue;
    // The incoming direction is the camera ray's, in the bounce's shading frame: above the surface.
    EXPECT_LT(viewer->brdfExplorer.thetaDeg, 90.0f);
    EXPECT_NEAR(std::cos(glm::radians(viewer->brdfExplorer.thetaDeg)), glm::dot(-first.direction, first.shadingNormal), 1e-4f);
    EXPECT_EQ(sceneToJson(viewer->scene()), before);
}

} // namespace
} // namespace raylab::ui
