// The workspace: every panel, laid out for the window on first use.
#include "panels/panels.h"

#include <imgui.h>

#include <algorithm>

namespace raylab::ui {

void drawWorkspace(Viewer& viewer, UiState& ui, float W, float H) {
    // First-use layout: controls on the left, the image in the middle, inspection on the right,
    // stats and log under the image. imgui.ini remembers any change.
    const float left = 330.0f, right = 330.0f, bottom = 230.0f;
    const float mid = std::max(200.0f, W - left - right);
    auto place = [](float x, float y, float w, float h) {
        ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(w, h), ImGuiCond_FirstUseEver);
    };
    place(left, 0, mid, H - bottom);
    drawViewport(viewer, ui);
    place(0, 0, left, H * 0.62f);
    drawRenderPanel(viewer, ui);
    place(0, H * 0.62f, left, H * 0.38f);
    drawCameraPanel(viewer, ui);
    place(left + mid, 0, right, H * 0.40f);
    drawMaterialPanel(viewer, ui);
    place(left + mid, H * 0.40f, right, H * 0.22f);
    drawOverlaysPanel(viewer, ui);
    place(left + mid, H * 0.62f, right, H * 0.38f);
    drawDebugPanel(viewer, ui);
    place(left, H - bottom, mid * 0.5f, bottom);
    drawStatsPanel(viewer, ui);
    place(left + mid * 0.5f, H - bottom, mid * 0.5f, bottom);
    drawLogPanel(viewer, ui);
    // Opened from the Overlays panel, an inspection or "explore": over the image's right side.
    place(left + mid * 0.35f, 20, mid * 0.65f, H * 0.45f);
    drawInspectorPanel(viewer, ui);
    place(left + mid * 0.3f, H * 0.3f, mid * 0.7f, H * 0.5f);
    drawBrdfExplorerPanel(viewer, ui);
    drawTeachWindow(viewer, ui, H);   // on top, when open (F1)
    // The presenter view on one screen (F2), over the image's right half; with its own window the
    // window loop draws it there.
    if (ui.presenter.show && !ui.presenter.ownWindow) {
        place(left + mid * 0.5f, 20, mid * 0.5f, H * 0.6f);
        if (ImGui::Begin("Presenter", &ui.presenter.show)) drawPresenterPanel(ui);
        ImGui::End();
    }
}

} // namespace raylab::ui
