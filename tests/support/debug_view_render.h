#pragma once
// A traced debug view rendered to the scene's render.spp, as raylab-render --debug-view writes it.
#include "render/debug_buffers.h"
#include "render/progressive_render.h"
#include "render/tracer_variants.h"

namespace raylab::test {

inline Image renderView(const Scene& scene, DebugView view, int bounce = 0) {
    PathTracer tracer(variantOptions(TracerVariant::Views, TracerEntry::Fragment));
    tracer.setScene(scene);
    setTracedView(tracer.program(), view, bounce);
    renderProgressively(tracer, scene.render);
    return tracer.readImage();
}

} // namespace raylab::test
