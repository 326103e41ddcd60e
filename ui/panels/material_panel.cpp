// Material panel: the outliner (every object, click to select), the selected object's keys and its
// material's keys, all built from the parameter tables so new keys show up without UI changes.
#include "panels/panels.h"
#include "panels/param_widget.h"

#include <imgui.h>

#include <string>

namespace raylab::ui {

void drawMaterialPanel(Viewer& viewer, UiState&) {
    if (!ImGui::Begin("Material")) {
        ImGui::End();
        return;
    }
    if (!viewer.hasScene()) {
        ImGui::End();
        return;
    }
    Scene& scene = viewer.scene();
    ImGui::PushItemWidth(-80.0f);
    ImGui::TextDisabled("Click an object in the viewport or here.");
    if (ImGui::BeginListBox("##outliner", ImVec2(-1, 6 * ImGui::GetTextLineHeightWithSpacing()))) {
        for (int i = 0; i < int(scene.spheres.size()); ++i) {
            const Sphere& s = scene.spheres[std::size_t(i)];
            const std::string name = std::to_string(i) + "  sphere  " +
                                     (s.material < int(scene.materials.size()) ? scene.materials[std::size_t(s.material)].name : "?");
            if (ImGui::Selectable(name.c_str(), viewer.selected == i)) viewer.selected = i;
        }
        ImGui::EndListBox();
    }
    const int sel = viewer.selected;
    if (sel >= 0 && sel < int(scene.spheres.size())) {
        ImGui::Separator();
        ImGui::Text("object %d", sel);
        for (const SphereParamSpec& p : sphereParameters())
            paramWidget(viewer, resolveParam(viewer.scene(), "objects." + std::to_string(sel) + "." + std::string(p.key)));
        // Material assignment.
        const int m = scene.spheres[std::size_t(sel)].material;
        if (ImGui::BeginCombo("material", scene.materials[std::size_t(m)].name.c_str())) {
            for (int j = 0; j < int(scene.materials.size()); ++j)
                if (ImGui::Selectable(scene.materials[std::size_t(j)].name.c_str(), j == m)) {
                    viewer.scene().spheres[std::size_t(sel)].material = j;
                    viewer.sceneChanged(Trigger::ReloadScene);
                }
            ImGui::EndCombo();
        }
        ImGui::Separator();
        ImGui::TextWrapped("material '%s' (shared by every object that uses it)", viewer.scene().materials[std::size_t(m)].name.c_str());
        for (const MaterialParamSpec& p : materialParameters())
            paramWidget(viewer, resolveParam(viewer.scene(), "materials." + std::to_string(m) + "." + std::string(p.key)));
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

} // namespace raylab::ui
