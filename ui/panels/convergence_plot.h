#pragma once
// A log–log plot of convergence series (error against samples per pixel or seconds) drawn with
// ImDrawList: decade grid lines, one polyline per series, and a dashed reference slope −1/2.
#include "stats/convergence_series.h"

#include <imgui.h>

#include <string>
#include <vector>

namespace raylab::ui {

struct PlotSeries {
    const stats::ConvergenceSeries* series = nullptr;
    std::string label;
    ImU32 colour = 0;
};

// bySeconds: x is tracing time instead of spp. Draws into a region of the given height.
void drawConvergencePlot(const std::vector<PlotSeries>& series, bool bySeconds, float height);

} // namespace raylab::ui
