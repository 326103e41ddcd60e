#include "panels/sample_points_plot.h"

#include "app/ui_state.h"
#include "app/viewer.h"
#include "inspect/sample_points.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace raylab::ui {

void drawSamplePointsPlot(Viewer& viewer, UiState& ui) {
    SamplePointsQuery& q = ui.samplePoints;
    int pair = int(q.pair);
    const std::string current(kSamplePairNames[pair]);
    if (ImGui::BeginCombo("points of", current.c_str())) {
        for (int i = 0; i < 4; ++i) {
            const std::string label(kSamplePairNames[i]);
            if (ImGui::Selectable(label.c_str(), i == pair)) q.pair = SamplePair(i);
        }
        ImGui::EndCombo();
    }
    if (q.pair == SamplePair::Bsdf || q.pair == SamplePair::Light)
        ImGui::SliderInt("bounce", &q.bounce, 0, std::max(viewer.scene().render.maxBounces - 1, 0), "%d",
                         ImGuiSliderFlags_AlwaysClamp);
    int count = int(q.count);
    if (ImGui::SliderInt("samples", &count, 1, 1024, "%d", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
        q.count = std::uint32_t(count);

    // The shader's pixel: rows from the bottom (the inspector's rows are from the top).
    const Inspection& in = viewer.inspection;
    const int w = viewer.imageWidth(), h = viewer.imageHeight();
    const int x = in.active() ? in.x() : w / 2, y = in.active() ? in.y() : h / 2;
    const RenderSettings& r = viewer.scene().render;
    q.sampler = r.sampler;
    q.seed = r.seed;
    q.spp = std::uint32_t(std::max(r.spp, 1));
    q.pixel = glm::uvec2(std::uint32_t(std::max(x, 0)), std::uint32_t(std::max(h - 1 - y, 0)));
    q.lens = viewer.tracer() == nullptr || viewer.tracer()->features().depthOfField;
    q.first = 0;
    const std::uint32_t dim = samplePairDimension(q.pair, q.bounce, q.lens);
    ImGui::Text("pixel (%d, %d)%s: samples 0-%u, dimensions %u-%u", x, y, in.active() ? "" : " (centre)", q.count - 1,
                dim, dim + 1);

    const float side = std::min(ImGui::GetContentRegionAvail().x, 240.0f);
    const ImVec2 o = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##points", ImVec2(side, side));
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(o, ImVec2(o.x + side, o.y + side), IM_COL32(20, 20, 24, 255));
    for (int k = 1; k < 4; ++k) {   // quarters: where a (0,2)-net's first 4 points go
        const float t = side * float(k) / 4.0f;
        dl->AddLine(ImVec2(o.x + t, o.y), ImVec2(o.x + t, o.y + side), IM_COL32(70, 70, 80, 255));
        dl->AddLine(ImVec2(o.x, o.y + t), ImVec2(o.x + side, o.y + t), IM_COL32(70, 70, 80, 255));
    }
    const auto points = samplePoints(q);
    for (std::size_t i = 0; i < points.size(); ++i) {
        // Earlier samples are brighter: the order in which a sampler fills the square shows.
        const float age = points.size() > 1 ? float(i) / float(points.size() - 1) : 0.0f;
        const ImU32 colour = ImGui::ColorConvertFloat4ToU32(ImVec4(1.0f, 0.85f - 0.6f * age, 0.2f + 0.6f * age, 1.0f));
        dl->AddCircleFilled(ImVec2(o.x + points[i].x * side, o.y + (1.0f - points[i].y) * side), 2.0f, colour);
    }
    dl->AddRect(o, ImVec2(o.x + side, o.y + side), IM_COL32(150, 150, 160, 255));
}

} // namespace raylab::ui
