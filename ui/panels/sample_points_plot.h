#pragma once
// The sample-points plot of the Render panel: the 2D points the viewer's sampler gives the
// inspected pixel (the image centre before an inspection) in one dimension pair, over its first N
// samples, drawn with ImDrawList in the unit square (inspect/sample_points.h makes them).
namespace raylab::ui {

class Viewer;
struct UiState;

void drawSamplePointsPlot(Viewer& viewer, UiState& ui);

} // namespace raylab::ui
