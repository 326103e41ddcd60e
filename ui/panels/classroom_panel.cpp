// The Classroom tab of the Teach window: UI scale for projectors, bounce stepping, the renderer's
// stages, the A/B split screen, and the live convergence plot.
#include "app/actions.h"
#include "panels/convergence_plot.h"
#include "panels/panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <string>

namespace raylab::ui {
namespace {

const char* const kStages[] = {"primary", "emission", "lambert", "ggx", "textures", "full"};
const char* const kStageHelp[] = {"camera rays only: flat albedo", "+ emitters and sky seen directly",
                                  "+ path tracing, Lambert only", "+ GGX, Fresnel and glass", "+ textures",
                                  "+ depth of field (everything)"};

void overrideEditor(Viewer& viewer, UiState& ui, int side) {
    ImGui::PushID(side);
    static std::string text[2];
    ImGui::TextUnformatted(ui.split.label(side).c_str());
    ImGui::SetNextItemWidth(-60.0f);
    const bool enter = ImGui::InputTextWithHint("##kv", "render.nee=true", &text[side], ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Add") || enter) {
        const auto eq = text[side].find('=');
        const std::string error = eq == std::string::npos
                                      ? std::string("expected KEY=VALUE")
                                      : ui.split.addOverride(side, text[side].substr(0, eq), text[side].substr(eq + 1), viewer.scene());
        if (!error.empty()) viewer.log().error("split " + std::string(side ? "B" : "A") + ": " + error);
        else text[side].clear();
    }
    ImGui::PopID();
}

} // namespace

void drawClassroomPanel(Viewer& viewer, UiState& ui) {
    if (ImGui::CollapsingHeader("Projector", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::SetNextItemWidth(160.0f);
        ImGui::SliderFloat("UI scale (Ctrl +/-/0)", &ui.uiScale, kMinUiScale, kMaxUiScale, "%.2f", ImGuiSliderFlags_AlwaysClamp);
        ImGui::Checkbox("class mode: answers only on the presenter view", &ui.presenter.classMode);
        ImGui::Checkbox(buttonLabel("presenter view", KeyAction::TogglePresenter).c_str(), &ui.presenter.show);
    }
    if (!viewer.hasScene()) return;
    if (ImGui::CollapsingHeader("Bounce stepping", ImGuiTreeNodeFlags_DefaultOpen)) {
        const int k = viewer.bounceStep();
        if (ImGui::Button("Bounce 1")) viewer.setBounceStep(1);
        ImGui::SameLine();
        if (ImGui::Button("Next bounce")) viewer.setBounceStep(k + 1);
        ImGui::SameLine();
        if (ImGui::Button("Off")) viewer.setBounceStep(0);
        if (k > 0) ImGui::Text("light after at most %d bounce%s (bounce views 0..%d)", k, k == 1 ? "" : "s", k);
        else ImGui::TextDisabled("off: render.max_bounces %d", viewer.scene().render.maxBounces);
    }
    if (ImGui::CollapsingHeader("Renderer stage", ImGuiTreeNodeFlags_DefaultOpen)) {
        const int stage = int(viewer.scene().render.stage);
        for (int i = 0; i < 6; ++i) {
            if (ImGui::RadioButton(kStages[i], stage == i) && stage != i) viewer.document().set("render.stage", kStages[i]);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kStageHelp[i]);
            if (i % 3 != 2) ImGui::SameLine();
        }
    }
    if (ImGui::CollapsingHeader("A/B split screen", ImGuiTreeNodeFlags_DefaultOpen)) {
        bool on = ui.split.on();
        int budget = int(ui.split.budget());
        if (ImGui::Checkbox("split", &on)) on ? ui.split.start(SplitBudget(budget)) : ui.split.stop();
        ImGui::SameLine();
        if (ImGui::RadioButton("equal samples", budget == 0) && on) ui.split.start(SplitBudget::EqualSamples);
        ImGui::SameLine();
        if (ImGui::RadioButton("equal time", budget == 1) && on) ui.split.start(SplitBudget::EqualTime);
        if (ImGui::Button("Preset: BSDF sampling | NEE + MIS")) {
            ui.split.stop();
            ui.split.addOverride(0, "render.nee", "false", viewer.scene());
            ui.split.addOverride(1, "render.nee", "true", viewer.scene());
            ui.split.addOverride(1, "render.mis", "true", viewer.scene());
            ui.split.start(SplitBudget::EqualTime);
        }
        overrideEditor(viewer, ui, 0);
        overrideEditor(viewer, ui, 1);
        ImGui::SetNextItemWidth(160.0f);
        ImGui::SliderFloat("divider", &ui.split.divider, 0.0f, 1.0f, "%.2f");
        if (ui.split.on()) {
            const SplitAccounting& a = ui.split.accounting();
            for (int i = 0; i < 2; ++i)
                ImGui::Text("%s: %llu spp, %.2f s traced", i ? "B" : "A", (unsigned long long)a.side(i).spp, a.side(i).seconds);
            if (ui.split.budget() == SplitBudget::EqualTime)
                ImGui::TextWrapped("time apart %.3f s (bound: the longest pass, %.3f s)", a.imbalance(), a.bound(ui.split.rpp()));
        }
    }
    if (ImGui::CollapsingHeader("Convergence", ImGuiTreeNodeFlags_DefaultOpen)) {
        static bool bySeconds = false;
        ImGui::Checkbox("against time (else spp)", &bySeconds);
        ImGui::TextDisabled("relative RMSE estimated from the image at each doubling; grey: slope -1/2");
        std::vector<PlotSeries> series;
        if (ui.split.on()) {
            series.push_back({&ui.split.series(0), "A", IM_COL32(255, 170, 60, 255)});
            series.push_back({&ui.split.series(1), "B", IM_COL32(90, 180, 255, 255)});
        } else {
            series.push_back({&ui.convergence, "image", IM_COL32(255, 170, 60, 255)});
        }
        drawConvergencePlot(series, bySeconds, std::max(140.0f, ImGui::GetContentRegionAvail().y - 4.0f));
    }
}

} // namespace raylab::ui
