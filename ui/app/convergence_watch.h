#pragma once
// Feeds the viewer's progressive beauty image to the live convergence plot's series
// (stats/convergence_series.h): a readback only when the samples have doubled; a new series
// whenever accumulation restarts. Call once per frame.
#include "app/ui_state.h"
#include "app/viewer.h"

namespace raylab::ui {

void watchConvergence(const Viewer& viewer, UiState& ui);

} // namespace raylab::ui
