#pragma once
// What the Python module keeps on its GL thread between calls: compiled tracers (a compile costs
// seconds on llvmpipe, a render of a small image milliseconds), the path inspector and the GLSL
// sampler harness. Lives and dies on the GlWorker's thread, with the context current.
#include "inspect/path_inspector.h"
#include "render/path_tracer.h"
#include "render/tracer_variants.h"
#include "selftest/gpu_sampler.h"

#include <memory>
#include <string>

namespace raylab::python {

struct GlState {
    std::string context;   // the backend, GL_RENDERER and GL_VERSION

    // The tracer of `variant` for `entry`, made on first use; each keeps its own compiled variants.
    PathTracer& tracer(TracerEntry entry, TracerVariant variant) {
        TracerVariants& cache = entry == TracerEntry::Compute ? compute_ : fragment_;
        if (PathTracer* t = cache.find(variant)) return *t;
        return cache.keep(variant, cache.compile(variant, nullptr));
    }
    PathInspector& inspector() {
        if (!inspector_) inspector_ = std::make_unique<PathInspector>();
        return *inspector_;
    }
    GpuSampler& sampler() {
        if (!sampler_) sampler_ = std::make_unique<GpuSampler>();
        return *sampler_;
    }

private:
    TracerVariants fragment_{TracerEntry::Fragment};
    TracerVariants compute_{TracerEntry::Compute};
    std::unique_ptr<PathInspector> inspector_;
    std::unique_ptr<GpuSampler> sampler_;
};

} // namespace raylab::python
