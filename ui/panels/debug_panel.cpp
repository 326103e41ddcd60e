// Debug panel: the debug view, its scales, a colour legend, and the value under the cursor.
#include "panels/panels.h"
#include "panels/heat_legend.h"
#include "panels/param_widget.h"
#include "shaders/include/fragment_layout.glsl"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace raylab::ui {
namespace {

void legend(const char* lo, const char* hi) {
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float w = ImGui::GetContentRegionAvail().x, h = 12.0f;
    drawHeatLegend(ImGui::GetWindowDrawList(), p, w, h, lo, hi);
    ImGui::Dummy(ImVec2(w, h + ImGui::GetTextLineHeightWithSpacing()));
}

// A heat map's scale: automatic (the largest count, `autoNote` after it in the legend) or a count
// dragged, shown as `format`; then the legend from 0.
void heatScaleControls(Viewer& viewer, const char* format, const char* autoNote) {
    if (ImGui::Checkbox("auto scale", &viewer.heatScaleAuto)) viewer.redisplay();
    if (!viewer.heatScaleAuto) {
        ImGui::SameLine();
        if (ImGui::DragFloat("red at", &viewer.heatScale, 0.5f, 1.0f, 1e7f, format)) viewer.redisplay();
    }
    const std::string hi = std::to_string(std::llround(viewer.heatScaleInUse())) + (viewer.heatScaleAuto ? autoNote : "");
    legend("0", hi.c_str());
}

// The traced view's keys, and the splits that put it beside the render or the baked map.
void ambientOcclusionControls(Viewer& viewer, UiState& ui) {
    for (const ParamSpec& p : sceneParameters())
        if (p.section() == "ao") paramWidget(viewer, resolveParam(viewer.scene(), p.key));
    if (ImGui::Button("AO beside the render")) ui.split.startViews(DebugView::Ao, DebugView::Beauty);
    const auto& materials = viewer.scene().materials;
    const bool baked = std::any_of(materials.begin(), materials.end(), [](const Material& m) { return m.occlusionTextureIndex >= 0; });
    if (baked) {
        ImGui::SameLine();
        if (ImGui::Button("baked beside traced")) ui.split.startViews(DebugView::BakedAo, DebugView::Ao);
    }
    if (ui.split.on() && ImGui::Button("split off")) ui.split.stop();
    ImGui::TextDisabled("The path tracer ignores baked maps: it finds occlusion by tracing (scenes/FORMAT.md).");
}

} // namespace

void drawDebugPanel(Viewer& viewer, UiState& ui) {
    if (!ImGui::Begin("Debug views")) {
        ImGui::End();
        return;
    }
    int column = 0;
    for (DebugView v : kDebugViews) {
        const std::string name(debugViewName(v));
        if (column++ % 3 != 0) ImGui::SameLine(float((column - 1) % 3) * 105.0f + 8.0f);
        if (ImGui::RadioButton(name.c_str(), viewer.debugView() == v)) viewer.setDebugView(v);
    }
    // The view's own controls, its legend line from the view table, then what follows the legend.
    switch (viewer.debugView()) {
    case DebugView::Depth:
        if (ImGui::DragFloat("black at distance", &viewer.depthScale, 0.1f, 0.01f, 1e5f)) viewer.redisplay();
        break;
    case DebugView::Noise:
        if (ImGui::DragFloat("red at rel. error", &viewer.noiseScale, 0.005f, 0.001f, 10.0f)) viewer.redisplay();
        break;
    case DebugView::BounceK: {
        int k = viewer.debugBounce();
        if (ImGui::SliderInt("bounce k", &k, 0, std::max(1, viewer.scene().render.maxBounces))) viewer.setDebugBounce(k);
        break;
    }
    default:
        break;
    }
    const std::string legendText(debugViewInfo(viewer.debugView()).legend);
    if (!legendText.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", legendText.c_str());
        ImGui::PopStyleColor();
    }
    switch (viewer.debugView()) {
    case DebugView::Noise: {
        const std::string hi = std::to_string(viewer.noiseScale).substr(0, 5);
        legend("0", hi.c_str());
        break;
    }
    case DebugView::Boxes:
    case DebugView::Triangles: {
        heatScaleControls(viewer, "%.0f tests", " (max of one ray)");
        ImGui::TextDisabled("Mean over the pixel's samples. Up to 16 objects the top level is a plain loop:\n"
                            "spheres cost no box tests there.");
        break;
    }
    case DebugView::Samples: {
        heatScaleControls(viewer, "%.0f samples", " (most of a pixel)");
        const PathTracer* t = viewer.tracer();
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        if (t && t->adaptive())
            ImGui::TextWrapped("adaptive: %llu spp on average; each %dx%d block shares one count, and a pass goes to "
                               "the blocks whose error falls most for its time (bench/adaptive_sampling.md)",
                               static_cast<unsigned long long>(t->samplesPerPixel()), int(glsl::FRAGMENT_BLOCK),
                               int(glsl::FRAGMENT_BLOCK));
        else
            ImGui::TextWrapped("even spreading: every pixel holds the same samples (render.adaptive off, or not in "
                               "effect with this sampler)");
        ImGui::PopStyleColor();
        break;
    }
    case DebugView::Ao:
    case DebugView::BakedAo:
        ambientOcclusionControls(viewer, ui);
        break;
    default:
        break;
    }
    ImGui::Checkbox("value under the cursor", &ui.pixelTooltip);
    ImGui::End();
}

} // namespace raylab::ui
