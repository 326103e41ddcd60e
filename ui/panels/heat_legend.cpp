#include "panels/heat_legend.h"

#include <algorithm>

namespace raylab::ui {

ImU32 heatColour(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    const float r = std::clamp(2.0f * t - 0.5f, 0.0f, 1.0f);
    const float g = std::clamp(t < 0.5f ? 2.0f * t : 2.0f - 2.0f * t + 0.5f, 0.0f, 1.0f);
    const float b = std::clamp(1.0f - 2.0f * t, 0.0f, 1.0f);
    return ImGui::GetColorU32(ImVec4(r, g, b, 1.0f));
}

void drawHeatLegend(ImDrawList* dl, ImVec2 p, float w, float h, const char* lo, const char* hi) {
    const int n = 32;
    for (int i = 0; i < n; ++i)
        dl->AddRectFilled(ImVec2(p.x + w * float(i) / n, p.y), ImVec2(p.x + w * float(i + 1) / n, p.y + h),
                          heatColour((float(i) + 0.5f) / n));
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    dl->AddText(ImVec2(p.x, p.y + h + 1.0f), text, lo);
    dl->AddText(ImVec2(p.x + w - ImGui::CalcTextSize(hi).x, p.y + h + 1.0f), text, hi);
}

} // namespace raylab::ui
