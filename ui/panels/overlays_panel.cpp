// Overlays panel: which wireframes the viewport draws over the image (viewport_panel.cpp draws
// them with the tracer's own camera maths, app/view_geometry.h).
#include "panels/panels.h"

#include <imgui.h>

#include <algorithm>

namespace raylab::ui {

void drawOverlaysPanel(Viewer& viewer, UiState&) {
    if (!ImGui::Begin("Overlays")) {
        ImGui::End();
        return;
    }
    ImGui::Checkbox("bounding boxes", &viewer.overlays.boxes);
    ImGui::SameLine();
    ImGui::Checkbox("selected only", &viewer.overlays.selectedOnly);
    ImGui::TextDisabled("Boxes: yellow, the selected object's: cyan.");
    ImGui::Checkbox("BVH level", &viewer.overlays.bvh);
    ImGui::SameLine();
    ImGui::Checkbox("mesh BVHs", &viewer.overlays.meshBvh);
    ImGui::SliderInt("depth", &viewer.overlays.bvhDepth, 0, std::max(1, viewer.geometry() ? viewer.geometry()->maxDepth : 1));
    ImGui::TextDisabled("BVH nodes at that depth (and shallower leaves): top level magenta, meshes orange.");
    ImGui::Checkbox("lights", &viewer.overlays.lights);
    ImGui::TextDisabled("A gizmo per light: point a star, spot its cone, sun an arrow from the centre; selected cyan.");
    ImGui::Separator();
    ImGui::Checkbox("inspect mode (a click inspects)", &viewer.inspection.clickInspects);
    ImGui::Checkbox("Inspector", &viewer.inspection.panelOpen);
    ImGui::SameLine();
    ImGui::Checkbox("BRDF explorer", &viewer.brdfExplorer.panelOpen);
    ImGui::End();
}

} // namespace raylab::ui
