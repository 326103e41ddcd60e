#include "app/convergence_watch.h"

namespace raylab::ui {

void watchConvergence(const Viewer& viewer, UiState& ui) {
    if (!viewer.hasScene() || viewer.debugView() != DebugView::Beauty) return;
    if (viewer.stats().restarts != ui.convergenceRun) {
        ui.convergence.reset();
        ui.convergenceRun = viewer.stats().restarts;
    }
    const std::uint64_t spp = viewer.tracer()->samplesPerPixel();
    if (ui.convergence.wants(spp)) ui.convergence.add(spp, viewer.stats().traceSeconds, viewer.tracer()->readImage());
}

} // namespace raylab::ui
