// The A/B split screen over the viewport's image rectangle: side A left of the divider, side B
// right of it, labels, and a divider that the mouse drags (grab it within a few pixels).
#include "panels/panels.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace raylab::ui {

void drawSplitView(UiState& ui, const ImageRect& r) {
    if (!ui.split.on()) return;
    const unsigned a = ui.split.displayTexture(0), b = ui.split.displayTexture(1);
    if (!a || !b) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float d = std::clamp(ui.split.divider, 0.0f, 1.0f);
    const float xd = r.x + d * r.width;
    // GL textures start at the bottom row: flip v.
    dl->AddImage(ImTextureID(std::uintptr_t(a)), ImVec2(r.x, r.y), ImVec2(xd, r.y + r.height), ImVec2(0, 1), ImVec2(d, 0));
    dl->AddImage(ImTextureID(std::uintptr_t(b)), ImVec2(xd, r.y), ImVec2(r.x + r.width, r.y + r.height), ImVec2(d, 1), ImVec2(1, 0));
    dl->AddLine(ImVec2(xd, r.y), ImVec2(xd, r.y + r.height), IM_COL32(255, 255, 255, 220), 2.0f);
    const SplitAccounting& acc = ui.split.accounting();
    char text[256];
    for (int side = 0; side < 2; ++side) {
        std::snprintf(text, sizeof text, "%s  (%llu spp, %.2f s)", ui.split.label(side).c_str(),
                      (unsigned long long)acc.side(side).spp, acc.side(side).seconds);
        const ImVec2 size = ImGui::CalcTextSize(text);
        const float x = side == 0 ? r.x + 4.0f : r.x + r.width - size.x - 4.0f;
        dl->AddRectFilled(ImVec2(x - 2, r.y + 2), ImVec2(x + size.x + 2, r.y + size.y + 4), IM_COL32(0, 0, 0, 160));
        dl->AddText(ImVec2(x, r.y + 3), side == 0 ? IM_COL32(255, 190, 90, 255) : IM_COL32(120, 200, 255, 255), text);
    }
    // The viewport's image button is the last item: a press near the divider drags it instead of
    // the camera (drawViewport checks ui.draggingDivider).
    const ImGuiIO& io = ImGui::GetIO();
    const bool near = std::abs(io.MousePos.x - xd) < 6.0f && io.MousePos.y >= r.y && io.MousePos.y <= r.y + r.height;
    if (near && ImGui::IsItemHovered()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    if (ImGui::IsItemActivated() && near) ui.draggingDivider = true;
    if (ui.draggingDivider) {
        // Kept through the release frame, so the viewport does not take the release as a click.
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) ui.split.divider = std::clamp((io.MousePos.x - r.x) / r.width, 0.0f, 1.0f);
        else if (!ImGui::IsItemDeactivated()) ui.draggingDivider = false;
    }
}

} // namespace raylab::ui
