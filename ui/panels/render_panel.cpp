// Render panel: files (open, save, screenshot, export), pause/resume/reset, resolution scale, every
// render.* key of the parameter table except the display ones (camera panel), and the estimator:
// sampler, next-event estimation, MIS, adaptive sampling, its switchable stages and the sample points
// of a pixel.
#include "panels/panels.h"

#include "app/actions.h"
#include "panels/param_widget.h"
#include "panels/sample_points_plot.h"
#include "scene/estimator_stages.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace raylab::ui {
namespace {

bool isEstimatorKey(const ParamSpec& p) {
    return p.key == "render.sampler" || p.key == "render.nee" || p.key == "render.mis" || p.key == "render.adaptive" ||
           std::ranges::find(kEstimatorStageKeys, p.key) != std::end(kEstimatorStageKeys);
}

// "zsobol sampler, NEE + MIS", then each estimator stage not at its default ("accel boxes"): what
// the progress line and the Estimator header say.
std::string estimatorLabel(const Scene& scene) {
    const RenderSettings& r = scene.render;
    std::string sampler = "?";
    for (const ParamSpec& p : sceneParameters())
        if (p.key == "render.sampler")
            for (const EnumName& n : p.enumNames)
                if (n.value == int(r.sampler) && !n.alias) sampler = std::string(n.name);
    std::string label = sampler + " sampler, " + (!r.nee ? "BSDF sampling only" : r.mis ? "NEE + MIS" : "NEE without MIS");
    if (adaptiveInEffect(r)) label += ", adaptive";
    const auto defaults = estimatorStages(Scene{});
    const auto stages = estimatorStages(scene);
    for (std::size_t i = 0; i < stages.size(); ++i)
        if (stages[i] != defaults[i]) label += ", " + stages[i].first + " " + stages[i].second;
    return label;
}

} // namespace

void drawRenderPanel(Viewer& viewer, UiState& ui) {
    if (!ImGui::Begin("Render")) {
        ImGui::End();
        return;
    }
    ImGui::PushItemWidth(-110.0f);   // room for the labels
    const float boxWidth = ImGui::GetContentRegionAvail().x - 130.0f;   // path boxes: room for the button
    if (ImGui::CollapsingHeader("Files", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::SetNextItemWidth(boxWidth);
        const bool enter = ImGui::InputText("##open", &ui.openPath, ImGuiInputTextFlags_EnterReturnsTrue);
        ImGui::SameLine();
        if ((ImGui::Button("Open") || enter) && !ui.openPath.empty()) viewer.openScene(ui.openPath);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Or drop a scene file on the window. Reloads when the file changes.");
        ImGui::SetNextItemWidth(boxWidth);
        ImGui::InputText("##save", &ui.savePath);
        ImGui::SameLine();
        if (ImGui::Button("Save scene")) runAction(KeyAction::SaveScene, viewer, ui);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(keyBinding(KeyAction::SaveScene).keyLabel).c_str());
        ImGui::SetNextItemWidth(boxWidth);
        ImGui::InputText("##shot", &ui.screenshotPath);
        ImGui::SameLine();
        if (ImGui::Button(buttonLabel("Screenshot", KeyAction::Screenshot).c_str())) runAction(KeyAction::Screenshot, viewer, ui);
        ImGui::SetNextItemWidth(boxWidth);
        ImGui::InputText("##export", &ui.exportPath);
        ImGui::SameLine();
        if (ImGui::Button(buttonLabel("Export", KeyAction::Export).c_str())) runAction(KeyAction::Export, viewer, ui);
        if (ImGui::Button(buttonLabel("Reload shaders", KeyAction::ReloadShaders).c_str())) runAction(KeyAction::ReloadShaders, viewer, ui);
        ImGui::SameLine();
        if (ImGui::Button(buttonLabel("Teach", KeyAction::ToggleTeach).c_str())) runAction(KeyAction::ToggleTeach, viewer, ui);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Lessons, classroom mode (split screen, stepping, stages) and the self-test");
    }
    if (!viewer.hasScene()) {
        ImGui::TextWrapped("No scene: open one above.");
        ImGui::PopItemWidth();
        ImGui::End();
        return;
    }
    if (ImGui::CollapsingHeader("Passes", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (ImGui::Button(buttonLabel(viewer.paused() ? "Resume" : "Pause", KeyAction::Pause).c_str())) runAction(KeyAction::Pause, viewer, ui);
        ImGui::SameLine();
        if (ImGui::Button(buttonLabel("Reset", KeyAction::Reset).c_str())) runAction(KeyAction::Reset, viewer, ui);
        float scale = viewer.resolutionScale();
        if (ImGui::SliderFloat("resolution scale", &scale, 0.125f, 2.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp))
            viewer.setResolutionScale(scale);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Traced size = render.width/height x scale (1 = the file's size)");
        ImGui::Text("traced image %d x %d", viewer.imageWidth(), viewer.imageHeight());
        const auto* t = viewer.tracer();
        const double target = double(viewer.scene().render.spp);
        const float progress = t ? float(double(t->samplesPerPixel()) / target) : 0.0f;
        const std::string text = std::to_string(t ? t->samplesPerPixel() : 0) + " / " +
                                 std::to_string(viewer.scene().render.spp) + " spp, " + estimatorLabel(viewer.scene());
        ImGui::ProgressBar(progress, ImVec2(-1, 0), text.c_str());
        for (const ParamSpec& p : sceneParameters()) {
            if (p.section() != "render" || p.name() == "exposure" || p.name() == "tone_map" || isEstimatorKey(p)) continue;
            paramWidget(viewer, resolveParam(viewer.scene(), p.key));
        }
    }
    if (ImGui::CollapsingHeader("Estimator", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("estimator: %s", estimatorLabel(viewer.scene()).c_str());
        for (const ParamSpec& p : sceneParameters()) {
            if (!isEstimatorKey(p)) continue;
            // The switch would do nothing with a sampler that lays out exactly spp samples per pixel.
            const bool inert = p.key == "render.adaptive" && !samplerTakesAdaptive(viewer.scene().render.sampler);
            ImGui::BeginDisabled(inert);
            paramWidget(viewer, resolveParam(viewer.scene(), p.key));
            ImGui::EndDisabled();
            if (inert) ImGui::TextDisabled("adaptive: off, the sobol or independent sampler takes it");
        }
        drawSamplePointsPlot(viewer, ui);
    }
    if (ImGui::CollapsingHeader("Sky")) {
        for (const ParamSpec& p : sceneParameters())
            if (p.section() == "sky") paramWidget(viewer, resolveParam(viewer.scene(), p.key));
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

} // namespace raylab::ui
