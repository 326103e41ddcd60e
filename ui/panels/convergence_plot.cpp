#include "panels/convergence_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace raylab::ui {

void drawConvergencePlot(const std::vector<PlotSeries>& series, bool bySeconds, float height) {
    double x0 = std::numeric_limits<double>::max(), x1 = 0, y0 = std::numeric_limits<double>::max(), y1 = 0;
    auto xOf = [&](const stats::ConvergencePoint& p) { return bySeconds ? p.seconds : p.spp; };
    for (const PlotSeries& s : series)
        for (const auto& p : s.series->points())
            if (xOf(p) > 0 && p.relativeRmse > 0) {
                x0 = std::min(x0, xOf(p));
                x1 = std::max(x1, xOf(p));
                y0 = std::min(y0, p.relativeRmse);
                y1 = std::max(y1, p.relativeRmse);
            }
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::Dummy(ImVec2(width, height));
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32(18, 18, 22, 255));
    if (x1 <= 0 || x0 >= x1 || y0 >= y1 * 0.999) {
        dl->AddText(ImVec2(origin.x + 6, origin.y + 6), IM_COL32(160, 160, 160, 255),
                    "Points appear each time the samples double (2, 4, 8, ... spp).");
        return;
    }
    // Whole decades around the data, in log10.
    const double lx0 = std::floor(std::log10(x0)), lx1 = std::ceil(std::log10(x1) + 1e-9);
    const double ly0 = std::floor(std::log10(y0)), ly1 = std::ceil(std::log10(y1) + 1e-9);
    const float padL = 40.0f, padB = 18.0f, padT = 4.0f, padR = 6.0f;
    const float w = width - padL - padR, h = height - padB - padT;
    auto toScreen = [&](double x, double y) {
        const double u = (std::log10(x) - lx0) / std::max(lx1 - lx0, 1e-9);
        const double v = (std::log10(y) - ly0) / std::max(ly1 - ly0, 1e-9);
        return ImVec2(origin.x + padL + float(u) * w, origin.y + padT + float(1.0 - v) * h);
    };
    char text[32];
    for (double d = lx0; d <= lx1 + 1e-9; d += 1) {
        const ImVec2 a = toScreen(std::pow(10.0, d), std::pow(10.0, ly0)), b = toScreen(std::pow(10.0, d), std::pow(10.0, ly1));
        dl->AddLine(a, b, IM_COL32(60, 60, 70, 255));
        std::snprintf(text, sizeof text, "%g", std::pow(10.0, d));
        dl->AddText(ImVec2(a.x - 8, a.y + 2), IM_COL32(170, 170, 170, 255), text);
    }
    for (double d = ly0; d <= ly1 + 1e-9; d += 1) {
        const ImVec2 a = toScreen(std::pow(10.0, lx0), std::pow(10.0, d)), b = toScreen(std::pow(10.0, lx1), std::pow(10.0, d));
        dl->AddLine(a, b, IM_COL32(60, 60, 70, 255));
        std::snprintf(text, sizeof text, "%g", std::pow(10.0, d));
        dl->AddText(ImVec2(origin.x + 2, a.y - 7), IM_COL32(170, 170, 170, 255), text);
    }
    // Reference: error ∝ spp^(−1/2) (or time^(−1/2) at a constant rate) through the first point.
    for (const PlotSeries& s : series) {
        const auto& pts = s.series->points();
        if (pts.empty()) continue;
        const double xa = xOf(pts.front()), ya = pts.front().relativeRmse;
        const double xb = std::pow(10.0, lx1), yb = ya * std::sqrt(xa / xb);
        dl->AddLine(toScreen(xa, ya), toScreen(xb, std::max(yb, std::pow(10.0, ly0))), IM_COL32(120, 120, 120, 160), 1.0f);
        break;
    }
    float legendY = origin.y + padT + 2;
    for (const PlotSeries& s : series) {
        std::vector<ImVec2> line;
        for (const auto& p : s.series->points())
            if (xOf(p) > 0 && p.relativeRmse > 0) line.push_back(toScreen(xOf(p), p.relativeRmse));
        if (line.size() >= 2) dl->AddPolyline(line.data(), int(line.size()), s.colour, 0, 2.0f);
        for (const ImVec2& q : line) dl->AddCircleFilled(q, 2.5f, s.colour);
        const double slope = s.series->slope();
        char legend[160];
        std::snprintf(legend, sizeof legend, "%s  slope %.2f", s.label.c_str(), std::isfinite(slope) ? slope : 0.0);
        dl->AddText(ImVec2(origin.x + width - padR - ImGui::CalcTextSize(legend).x, legendY), s.colour, legend);
        legendY += ImGui::GetFontSize();
    }
}

} // namespace raylab::ui
