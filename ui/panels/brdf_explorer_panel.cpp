// BRDF explorer panel: a thin view of app/brdf_explorer_model.h. The incoming direction comes from
// sliders, a drag on the small hemisphere disk, or an inspected bounce (Inspector: "explore").
// Draws the polar plot of f·cosθ in the plane of incidence, the heat maps of both hemispheres
// (equal-area disks) with the GPU sampler's directions over them, and the χ² verdict.
#include "panels/panels.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace raylab::ui {
namespace {

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// Black → red → yellow → white.
ImU32 heat(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    const auto ch = [](float v) { return int(std::clamp(v, 0.0f, 1.0f) * 255.0f); };
    return IM_COL32(ch(3.0f * t), ch(3.0f * t - 1.0f), ch(3.0f * t - 2.0f), 255);
}

// The incoming direction picked on a disk (top view of the hemisphere, equal-area).
void directionDisk(BrdfExplorerModel& m, float size) {
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##wo", ImVec2(size, size));
    const ImVec2 c(p0.x + size * 0.5f, p0.y + size * 0.5f);
    const float R = size * 0.5f - 2.0f;
    if (ImGui::IsItemActive()) {
        const ImVec2 mp = ImGui::GetIO().MousePos;
        glm::vec2 d((mp.x - c.x) / R, -(mp.y - c.y) / R);
        if (glm::length(d) > 1.0f) d = glm::normalize(d);
        const glm::vec2 a = anglesFromDirection(diskToDirection(d, false));
        m.thetaDeg = std::min(a.x, 89.0f);
        m.phiDeg = a.y;
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddCircleFilled(c, R, IM_COL32(40, 40, 50, 255));
    dl->AddCircle(c, R, IM_COL32(160, 160, 170, 255));
    if (m.thetaDeg <= 90.0f) {
        const glm::vec2 d = directionToDisk(m.wo());
        dl->AddLine(c, ImVec2(c.x + d.x * R, c.y - d.y * R), IM_COL32(120, 200, 255, 255));
        dl->AddCircleFilled(ImVec2(c.x + d.x * R, c.y - d.y * R), 4.0f, IM_COL32(120, 200, 255, 255));
    }
}

// f·cosθ (luminance) against the angle in the plane of incidence; wo in blue, the surface grey.
void polarPlot(const BrdfExplorerModel& m, float width) {
    const float height = width;
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(width, height));
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 c(p0.x + width * 0.5f, p0.y + height * 0.5f);
    const float R = width * 0.5f - 4.0f;
    dl->AddRectFilled(p0, ImVec2(p0.x + width, p0.y + height), IM_COL32(25, 25, 30, 255));
    dl->AddLine(ImVec2(p0.x, c.y), ImVec2(p0.x + width, c.y), IM_COL32(140, 140, 140, 255));
    dl->AddLine(c, ImVec2(c.x, p0.y), IM_COL32(80, 80, 80, 255));
    float peak = 0.0f;
    for (const PolarPoint& q : m.polar()) peak = std::max(peak, luminance(q.fCos));
    if (peak > 0.0f) {
        std::vector<ImVec2> pts;
        for (const PolarPoint& q : m.polar()) {
            const float a = glm::radians(q.angleDeg), r = luminance(q.fCos) / peak * R;
            pts.push_back(ImVec2(c.x + std::sin(a) * r, c.y - std::cos(a) * r));
        }
        dl->AddPolyline(pts.data(), int(pts.size()), IM_COL32(255, 200, 60, 255), 0, 2.0f);
    }
    const float t = glm::radians(m.thetaDeg);
    dl->AddLine(c, ImVec2(c.x - std::sin(t) * R, c.y - std::cos(t) * R), IM_COL32(120, 200, 255, 255), 2.0f);
    char label[64];
    std::snprintf(label, sizeof label, "peak f cos = %.3g", double(peak));
    dl->AddText(ImVec2(p0.x + 4, p0.y + 2), IM_COL32(200, 200, 200, 255), label);
}

// One hemisphere's heat map on its disk, the sampled directions that fell in it on top.
void hemisphereDisk(const BrdfExplorerModel& m, bool lower, float size, bool scatter) {
    const HemisphereMap& map = m.map();
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(size, size));
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const std::vector<float>& v = lower ? map.lower : map.upper;
    const float cellSize = size / float(std::max(map.n, 1));
    for (int row = 0; row < map.n; ++row)
        for (int col = 0; col < map.n; ++col) {
            const float value = v[std::size_t(row * map.n + col)];
            if (value < 0.0f) continue;
            const ImVec2 a(p0.x + float(col) * cellSize, p0.y + float(row) * cellSize);
            dl->AddRectFilled(a, ImVec2(a.x + cellSize + 0.5f, a.y + cellSize + 0.5f),
                              heat(map.maxValue > 0.0f ? std::sqrt(value / map.maxValue) : 0.0f));
        }
    const ImVec2 c(p0.x + size * 0.5f, p0.y + size * 0.5f);
    dl->AddCircle(c, size * 0.5f, IM_COL32(160, 160, 170, 255), 48);
    if (!scatter) return;
    const std::size_t shown = std::min<std::size_t>(m.samples().size(), 3000);
    for (std::size_t i = 0; i < shown; ++i) {
        const GpuSample& s = m.samples()[i];
        if (s.delta() || s.lobe() == 0 || (s.wi().z < 0.0f) != lower) continue;
        const glm::vec2 d = directionToDisk(s.wi());
        dl->AddCircleFilled(ImVec2(c.x + d.x * size * 0.5f, c.y - d.y * size * 0.5f), 1.2f, IM_COL32(80, 220, 255, 200), 6);
    }
}

} // namespace

void drawBrdfExplorerPanel(Viewer& viewer, UiState&) {
    BrdfExplorerModel& m = viewer.brdfExplorer;
    if (!m.panelOpen || !viewer.hasScene()) return;
    if (!ImGui::Begin("BRDF explorer", &m.panelOpen)) {
        ImGui::End();
        return;
    }
    const Scene& scene = viewer.scene();
    const int mat = m.resolvedMaterial(viewer);
    const std::string name = mat < 0 ? "none" : scene.materials[std::size_t(mat)].name;
    ImGui::SetNextItemWidth(180);
    if (ImGui::BeginCombo("material", (m.material < 0 ? "selected: " + name : name).c_str())) {
        if (ImGui::Selectable("the selected object's", m.material < 0)) m.material = -1;
        for (int i = 0; i < int(scene.materials.size()); ++i)
            if (ImGui::Selectable(scene.materials[std::size_t(i)].name.c_str(), m.material == i)) m.material = i;
        ImGui::EndCombo();
    }
    ImGui::BeginGroup();
    ImGui::SetNextItemWidth(150);
    ImGui::SliderFloat("theta in", &m.thetaDeg, 0.0f, 179.0f, "%.1f deg");
    ImGui::SetNextItemWidth(150);
    ImGui::SliderFloat("phi in", &m.phiDeg, 0.0f, 360.0f, "%.1f deg");
    ImGui::Checkbox("diffuse", &m.lobes.diffuse);
    ImGui::SameLine();
    ImGui::Checkbox("specular", &m.lobes.specular);
    ImGui::SameLine();
    ImGui::Checkbox("transmission", &m.lobes.transmission);
    ImGui::SetNextItemWidth(150);
    ImGui::SliderInt("samples", &m.sampleCount, 1000, 200000, "%d", ImGuiSliderFlags_Logarithmic);
    if (ImGui::Button("new samples")) ++m.seed;
    ImGui::EndGroup();
    ImGui::SameLine();
    directionDisk(m, 110.0f);
    m.update(viewer);
    if (!m.error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", m.error().c_str());
    if (!m.hasResults()) {
        ImGui::End();
        return;
    }
    const SamplerTest& t = m.test();
    ImGui::TextColored(t.pass ? ImVec4(0.4f, 1.0f, 0.4f, 1.0f) : ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s",
                       t.pass ? "PASS" : "FAIL");
    ImGui::SameLine();
    ImGui::Text("chi2 %.1f, dof %d, p = %.3g (alpha %.2g)%s", t.chi2.statistic, t.chi2.dof, t.chi2.pValue, t.alpha,
                t.chi2.sampleInZeroCell ? ", a sample where pdf = 0" : "");
    ImGui::Text("%d GPU samples, %d delta or none; integral of pdf %.4f; max |pdf - bsdfPdf| %.2g", t.samples,
                t.deltaOrNone, t.pdfIntegral, t.maxPdfMismatch);
    static bool scatter = true;
    const float avail = ImGui::GetContentRegionAvail().x;
    const float plot = std::clamp(avail * 0.38f, 120.0f, 320.0f);
    const float disk = std::clamp((avail - plot) * 0.5f - 12.0f, 80.0f, 260.0f);
    ImGui::BeginGroup();
    ImGui::TextUnformatted("f cos, plane of incidence");
    polarPlot(m, plot);
    ImGui::EndGroup();
    ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::TextUnformatted("upper hemisphere");
    hemisphereDisk(m, false, disk, scatter);
    ImGui::EndGroup();
    ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::TextUnformatted("lower (transmission)");
    hemisphereDisk(m, true, disk, scatter);
    ImGui::EndGroup();
    ImGui::Checkbox("show samples", &scatter);
    ImGui::SameLine();
    ImGui::TextUnformatted("  maps:");
    ImGui::SameLine();
    if (ImGui::RadioButton("f cos", !m.mapPdf)) m.mapPdf = false;
    ImGui::SameLine();
    if (ImGui::RadioButton("pdf (what the samples follow)", m.mapPdf)) m.mapPdf = true;
    ImGui::End();
}

} // namespace raylab::ui
