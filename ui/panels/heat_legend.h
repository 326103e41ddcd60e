#pragma once
// The colour ramp of the display shader's heat maps (shaders/entry/display.frag: noise, box and
// triangle tests) and a legend bar for it, shared by the Debug panel and the viewport.
#include <imgui.h>

namespace raylab::ui {

ImU32 heatColour(float t);   // blue → green → yellow → red for t in [0, 1]
// A bar of the ramp at `pos` (screen pixels) with `lo` under its left end and `hi` under its right.
void drawHeatLegend(ImDrawList* dl, ImVec2 pos, float width, float height, const char* lo, const char* hi);

} // namespace raylab::ui
