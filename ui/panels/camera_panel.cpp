// Camera panel: camera.* keys, click-to-focus, exposure and tone map, the speed of WASD/QE moves and
// a reminder of the mouse and key bindings (the moves themselves live in viewport_panel.cpp).
#include "panels/panels.h"
#include "panels/param_widget.h"

#include <imgui.h>

namespace raylab::ui {

void drawCameraPanel(Viewer& viewer, UiState& ui) {
    if (!ImGui::Begin("Camera")) {
        ImGui::End();
        return;
    }
    ImGui::PushItemWidth(-90.0f);
    if (viewer.hasScene()) {
        for (const ParamSpec& p : sceneParameters())
            if (p.section() == "camera") paramWidget(viewer, resolveParam(viewer.scene(), p.key));
        // Click-to-focus: the next click on the image sets focus_distance (app/focus_pick.h).
        if (ui.focusOnClick) {
            if (ImGui::Button("Cancel click to focus")) ui.focusOnClick = false;
            ImGui::SameLine();
            ImGui::TextUnformatted("click the image");
        } else if (ImGui::Button("Click to focus")) {
            ui.focusOnClick = true;
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The next click on the image sets camera.focus_distance to the depth (along the view\n"
                              "axis) of the surface there; with camera.aperture > 0 that surface becomes sharp.");
        paramWidget(viewer, resolveParam(viewer.scene(), "render.exposure"));
        paramWidget(viewer, resolveParam(viewer.scene(), "render.tone_map"));
        ImGui::SliderFloat("move speed", &viewer.cameraSpeed, 0.05f, 50.0f, "%.2f units/s", ImGuiSliderFlags_Logarithmic);
    }
    ImGui::PopItemWidth();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("Viewport: left drag orbits, right drag looks around (fly), wheel dollies, click "
                       "picks. Keys: WASD move, Q/E down/up, arrows turn, Shift = 4x speed.");
    ImGui::PopStyleColor();
    ImGui::End();
}

} // namespace raylab::ui
