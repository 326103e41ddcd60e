// Inspector panel: the pixel path inspector (app/inspection.h). Inspect mode turns viewport clicks
// into inspections; the table shows one path's estimator terms bounce by bounce; the viewport
// draws the paths over the image (drawPathOverlay, with the tracer's camera).
#include "panels/panels.h"

#include "inspect/path_record.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace raylab::ui {
namespace {

std::string rgb(glm::vec3 v) {
    char buf[64];
    if (v.x == v.y && v.y == v.z) std::snprintf(buf, sizeof buf, "%.4g", double(v.x));
    else std::snprintf(buf, sizeof buf, "%.3g %.3g %.3g", double(v.x), double(v.y), double(v.z));
    return buf;
}

void cell(const std::string& s) {
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(s.c_str());
}

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// A colour per path (golden-ratio hue steps), bright enough over dark and light renders.
ImU32 pathColour(int i, float alpha = 1.0f) {
    float r, g, b;
    ImGui::ColorConvertHSVtoRGB(std::fmod(0.93f + 0.618034f * float(i), 1.0f), 0.85f, 1.0f, r, g, b);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, alpha));
}

// A term's contribution, or "off" when the bounce view leaves it out of the value.
std::string added(bool counted, glm::vec3 v) { return counted ? rgb(v) : "off"; }

bool hasStageAlbedo(const PathRecord& p) {
    return std::any_of(p.bounces.begin(), p.bounces.end(), [](const BounceRecord& b) { return b.hasStageAlbedo; });
}

void bounceTable(Viewer& viewer, const PathRecord& p) {
    const Scene& scene = viewer.scene();
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
    // render.stage primary: one more column, the albedo that stage returns.
    const bool stage = hasStageAlbedo(p);
    std::vector<const char*> columns = {"#",  "hit", "lobe (P)",   "f",     "cos",     "pdf",         "f cos/pdf",
                                        "beta before", "beta after", "Le", "w", "Le w added", "light", "light w",
                                        "light added", "RR q",        "BRDF"};
    if (stage) columns.insert(columns.begin() + 2, "albedo added");
    if (!ImGui::BeginTable(stage ? "bounces+albedo" : "bounces", int(columns.size()), flags,
                           ImVec2(0, 11 * ImGui::GetTextLineHeightWithSpacing())))
        return;
    ImGui::TableSetupScrollFreeze(1, 1);
    for (const char* c : columns) ImGui::TableSetupColumn(c);
    ImGui::TableHeadersRow();
    for (std::size_t k = 0; k < p.bounces.size(); ++k) {
        const BounceRecord& b = p.bounces[k];
        ImGui::TableNextRow();
        ImGui::PushID(int(k));
        cell(std::to_string(k));
        if (b.hit) {
            const std::string m = b.material >= 0 && b.material < int(scene.materials.size())
                                      ? scene.materials[std::size_t(b.material)].name
                                      : std::to_string(b.material);
            cell(m + " #" + std::to_string(b.primitive) + " t=" + num(b.distance));
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("p %s\nNg %s\nNs %s\nin %s", rgb(b.position).c_str(), rgb(b.normal).c_str(),
                                  rgb(b.shadingNormal).c_str(), rgb(b.direction).c_str());
        } else {
            cell("sky");
        }
        if (stage) {
            cell(b.hasStageAlbedo ? added(b.emissionCounted, b.stageAlbedoAdded()) : "-");
            if (b.hasStageAlbedo && ImGui::IsItemHovered())
                ImGui::SetTooltip("render.stage primary: the first hit's albedo %s is the whole estimate", rgb(b.stageAlbedo).c_str());
        }
        if (b.sampled) {
            cell(lobeName(b.lobe) + " (" + num(b.lobeProbability) + ")");
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("out %s%s", rgb(b.sampledDirection).c_str(), b.delta ? "\ndelta lobe" : "");
            cell(rgb(b.f));
            cell(num(b.cosTheta));
            cell(num(b.pdf));
            cell(rgb(b.weight));
        } else {
            for (int i = 0; i < 5; ++i) cell("-");
        }
        cell(rgb(b.throughputBefore));
        cell(b.sampled ? rgb(b.throughputAfter) : "-");
        cell(rgb(b.emission));
        cell(num(b.emissionWeight));
        cell(added(b.emissionCounted, b.emissionAdded()));
        cell(b.lightStatus == LightStatus::None ? "-" : lightStatusName(b.lightStatus) + ": " + b.lightName);
        if (b.lightStatus != LightStatus::None && ImGui::IsItemHovered())
            ImGui::SetTooltip("%s (light %d), dir %s\nLe %s\nf cos %s, cos %.4g\nlight pdf %.4g, BSDF pdf %.4g\nMIS pdf %s",
                              b.lightName.c_str(), b.lightIndex, rgb(b.lightDirection).c_str(), rgb(b.lightRadiance).c_str(),
                              rgb(b.lightFCos).c_str(), double(b.lightCosTheta), double(b.lightPdf), double(b.lightBsdfPdf),
                              lightMisPdfText(b).c_str());
        cell(b.lightStatus == LightStatus::None ? "-" : num(b.lightMisWeight));
        cell(b.lightStatus == LightStatus::None ? "-" : added(b.lightCounted, b.lightAdded()));
        cell(b.rrOutcome < 0 ? "-" : num(b.rrProbability) + (b.rrOutcome ? " lived" : " died"));
        ImGui::TableNextColumn();
        if (b.hit && ImGui::SmallButton("explore")) {
            viewer.brdfExplorer.fromBounce(b);
            viewer.brdfExplorer.panelOpen = true;
        }
        ImGui::PopID();
    }
    ImGui::EndTable();
}

} // namespace

void drawInspectorPanel(Viewer& viewer, UiState&) {
    Inspection& in = viewer.inspection;
    in.update(viewer);
    if (!in.panelOpen) return;
    if (!ImGui::Begin("Inspector", &in.panelOpen)) {
        ImGui::End();
        return;
    }
    ImGui::Checkbox("inspect mode (click a pixel)", &in.clickInspects);
    ImGui::SameLine();
    ImGui::Checkbox("follow", &in.follow);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("record again when the image restarts");
    ImGui::SetNextItemWidth(120);
    ImGui::SliderInt("paths", &in.pathCount, 1, 64);
    if (in.active()) {
        ImGui::SameLine();
        if (ImGui::Button("record again")) in.inspect(viewer, in.x(), in.y());
        ImGui::SameLine();
        if (ImGui::Button("clear")) in.clear();
    }
    ImGui::Checkbox("overlay", &in.overlay.show);
    ImGui::SameLine();
    ImGui::Checkbox("normals", &in.overlay.normals);
    ImGui::SameLine();
    ImGui::Checkbox("sampled", &in.overlay.sampled);
    ImGui::SameLine();
    ImGui::Checkbox("shadow rays", &in.overlay.shadowRays);
    if (!in.active()) {
        ImGui::TextWrapped("No pixel inspected: tick inspect mode and click the image (script: inspect X Y).");
        ImGui::End();
        return;
    }
    const auto& paths = in.paths();
    ImGui::Text("pixel (%d, %d): %d paths from sample %llu", in.x(), in.y(), int(paths.size()),
                paths.empty() ? 0ULL : (unsigned long long)paths[0].sample);
    ImGui::SetNextItemWidth(200);
    const std::string current = in.shownPath < 0 ? "all (table: path 0)" : "path " + std::to_string(in.shownPath);
    if (ImGui::BeginCombo("shown", current.c_str())) {
        if (ImGui::Selectable("all (table: path 0)", in.shownPath < 0)) in.shownPath = -1;
        for (int i = 0; i < int(paths.size()); ++i) {
            const std::string name = "path " + std::to_string(i) + ": " + std::to_string(paths[std::size_t(i)].bounces.size()) +
                                     " bounces, value " + rgb(paths[std::size_t(i)].value);
            ImGui::PushStyleColor(ImGuiCol_Text, pathColour(i));
            if (ImGui::Selectable(name.c_str(), in.shownPath == i)) in.shownPath = i;
            ImGui::PopStyleColor();
        }
        ImGui::EndCombo();
    }
    // What the values are: the pixel's own under beauty and the bounce views, else beauty's.
    if (in.filter() == BounceFilter::Only)
        ImGui::TextWrapped("Recorded under the bounce view, k = %d: only light that reached the eye after exactly k "
                           "bounces counts; other terms show \"off\".", in.filterBounce());
    else if (in.filter() == BounceFilter::Direct)
        ImGui::TextWrapped("Recorded under the direct view: only bounces 0 and 1 count; other terms show \"off\".");
    else if (in.filter() == BounceFilter::Indirect)
        ImGui::TextWrapped("Recorded under the indirect view: only bounces 2 and more count; other terms show \"off\".");
    else if (tracedDebugView(viewer.debugView()))
        ImGui::TextWrapped("The %s view traces no light paths: these are the beauty estimator's terms, not the "
                           "pixel on screen.", std::string(debugViewName(viewer.debugView())).c_str());
    if (!paths.empty()) {
        const PathRecord& p = paths[std::size_t(std::max(in.shownPath, 0))];
        const glm::dvec3 sum = p.sumOfTerms();
        ImGui::Text("value %s  =  sum of beta (%s + light) %s%s", rgb(p.value).c_str(),
                    hasStageAlbedo(p) ? "Le w + albedo" : "Le w", rgb(glm::vec3(sum)).c_str(),
                    p.truncated ? "  (truncated)" : "");
        bounceTable(viewer, p);
    }
    static char exportPath[256] = "raylab-paths.json";
    ImGui::SetNextItemWidth(200);
    ImGui::InputText("##export", exportPath, sizeof exportPath);
    ImGui::SameLine();
    if (ImGui::Button("export")) in.exportPaths(viewer, exportPath);
    ImGui::SameLine();
    ImGui::TextDisabled(".json or .csv");
    ImGui::End();
}

void drawPathOverlay(Viewer& viewer, const ImageRect& r) {
    const Inspection& in = viewer.inspection;
    if (!in.active() || !in.overlay.show) return;
    const int w = viewer.imageWidth(), h = viewer.imageHeight();
    const PathOverlay o = pathOverlay(viewer.tracedScene(), w, h, in.paths(), in.overlay, in.shownPath);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.width, r.y + r.height), true);
    const auto at = [&](ImagePoint p) { return ImVec2(r.x + p.x / float(w) * r.width, r.y + p.y / float(h) * r.height); };
    for (const PathLine& l : o.lines) {
        ImU32 c = pathColour(l.path);
        float thickness = 2.0f;
        switch (l.kind) {
        case PathLineKind::Segment: break;
        case PathLineKind::Escape: c = pathColour(l.path, 0.6f); thickness = 1.0f; break;
        case PathLineKind::Normal: c = IM_COL32(80, 255, 80, 255); thickness = 1.0f; break;
        case PathLineKind::Sampled: c = IM_COL32(255, 160, 0, 255); thickness = 1.0f; break;
        case PathLineKind::ShadowVisible: c = IM_COL32(255, 255, 120, 200); thickness = 1.0f; break;
        case PathLineKind::ShadowBlocked: c = IM_COL32(255, 60, 60, 200); thickness = 1.0f; break;
        }
        dl->AddLine(at(l.segment.a), at(l.segment.b), c, thickness);
    }
    for (const PathDot& d : o.hits) {
        dl->AddCircleFilled(at(d.point), 3.0f, pathColour(d.path));
        dl->AddCircle(at(d.point), 3.0f, IM_COL32(0, 0, 0, 255));
    }
    // The inspected pixel itself.
    const ImVec2 a = at(ImagePoint{float(in.x()), float(in.y())}), b = at(ImagePoint{float(in.x() + 1), float(in.y() + 1)});
    dl->AddRect(ImVec2(a.x - 2, a.y - 2), ImVec2(b.x + 2, b.y + 2), IM_COL32(255, 255, 255, 255));
    dl->PopClipRect();
}

} // namespace raylab::ui
