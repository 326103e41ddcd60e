// The lights in the viewer without a window: the outliner lists them after the objects, a
// selected light shows its own type's keys, an edit goes through the scene document (the image
// restarts and the tracer's lights change), `selected.KEY` reaches the selected light, and the
// gizmo overlay draws.
#include "panels/panels.h"

#include "app/scene_light.h"
#include "app/script_runner.h"
#include "scene/scene_keys.h"
#include "support/panel_frame_test.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <numeric>

namespace raylab::ui {
namespace {

class LightPanelTest : public test::PanelFrameTest {
protected:
    void SetUp() override {
        PanelFrameTest::SetUp();
        openSmall("lights.json", 32, 18);
    }
    std::string materialPanel() {
        return windowText([&] { drawMaterialPanel(*viewer, ui); });
    }
    double imageSum() {
        for (int i = 0; i < 100000 && !viewer->converged(); ++i) viewer->update(1e-3);
        const Image img = viewer->tracer()->readImage();
        return std::accumulate(img.rgba.begin(), img.rgba.end(), 0.0);
    }
};

TEST_F(LightPanelTest, TheOutlinerListsTheLightsAndAPanelShowsTheSelectedOnesKeys) {
    // The outliner shows six rows: a selected light scrolls its row into view.
    viewer->selection.selectLight(1);
    EXPECT_EQ(viewer->selection.object(), -1);
    materialPanel();
    std::string text = materialPanel();
    for (const char* row : {"point light 0", "spot 1", "sun 2"}) EXPECT_NE(text.find(row), std::string::npos) << text;
    for (const char* key : {"position", "direction", "intensity", "power", "inner_angle", "outer_angle"})
        EXPECT_NE(text.find(key), std::string::npos) << key << "\n" << text;
    EXPECT_EQ(text.find("irradiance"), std::string::npos) << text;
    EXPECT_EQ(text.find("albedo"), std::string::npos) << "no material keys for a light\n" << text;
    viewer->selection.selectLight(2);
    text = materialPanel();
    for (const char* key : {"direction", "irradiance", "angular_radius"})
        EXPECT_NE(text.find(key), std::string::npos) << key << "\n" << text;
    EXPECT_EQ(text.find("inner_angle"), std::string::npos) << text;
    // Selecting an object deselects the light, and the other way round.
    viewer->selection.select(0);
    EXPECT_EQ(viewer->selection.light(), -1);
    viewer->selection.selectLight(7);
    EXPECT_EQ(viewer->selection.light(), -1) << "out of range: none";
}

TEST_F(LightPanelTest, AnEditOfALightsKeyRestartsTheImageAndChangesIt) {
    const double before = imageSum();
    const std::uint64_t restarts = viewer->stats().restarts;
    const std::vector<std::string> keys = lightKeys(viewer->scene(), 0);
    ASSERT_EQ(keys, (std::vector<std::string>{"lights.0.position", "lights.0.intensity", "lights.0.power"}));
    ASSERT_TRUE(viewer->document().set(resolveParam(viewer->scene(), keys[1]), ParamValue(glm::vec3(60.0f))))
        << viewer->document().lastError();
    EXPECT_EQ(viewer->scene().lights[0].intensity, glm::vec3(60.0f));
    EXPECT_GT(viewer->stats().restarts, restarts);
    const double after = imageSum();
    EXPECT_GT(after, before * 1.05) << "ten times the point light's intensity must show";
    // An edit the scene refuses leaves it unchanged.
    EXPECT_FALSE(viewer->document().set("lights.1.inner_angle", "40"));
    EXPECT_EQ(viewer->scene().lights[1].innerAngle, 18.0f);
}

TEST_F(LightPanelTest, TheScriptSelectsALightAndEditsItsSelectedKeys) {
    struct NoWindow : ScriptHost {
        void resizeWindow(int, int) override {}
        void dropFile(const std::string&) override {}
    } host;
    ScriptRunner runner(parseScript("select-light 1\nset selected.outer_angle 40\nselect-light 5\n", "s.txt"), 600.0);
    double t = 0.0;
    for (int i = 0; i < 100 && runner.step(*viewer, ui, host, t); ++i) t += 0.001;
    EXPECT_EQ(viewer->scene().lights[1].outerAngle, 40.0f);
    EXPECT_EQ(runner.failures(), 1) << "there is no light 5";
    EXPECT_EQ(viewer->selection.light(), 1);
}

TEST_F(LightPanelTest, TheLightGizmosDraw) {
    frame();
    const int before = ImGui::GetDrawData()->TotalVtxCount;
    viewer->overlays.lights = true;
    viewer->selection.selectLight(1);
    frame();
    EXPECT_GT(ImGui::GetDrawData()->TotalVtxCount, before);
}

} // namespace
} // namespace raylab::ui
