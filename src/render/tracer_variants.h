#pragma once
// The path tracer's variants for the debug views, and a cache of them compiled when first needed:
// the plain beauty tracer (raylab-render's image), one that also keeps per-pixel moments (noise and
// NaN views), one that traces the debug views, and one that traces them counting traversal (heat
// maps). Needs a current GL 4.5 context.
#include "render/debug_views.h"
#include "render/path_tracer.h"

#include <memory>
#include <string_view>

namespace raylab {

enum class TracerVariant { Beauty = 0, Moments = 1, Views = 2, Counts = 3 };

// The variant that traces what `view` shows.
TracerVariant variantFor(DebugView view);
// The options that compile `variant` with the tracer's `entry` point.
TracerOptions variantOptions(TracerVariant variant, TracerEntry entry);
// What the variant adds to the tracer's own variant name ("" for the beauty tracer).
std::string_view variantSuffix(TracerVariant variant);

class TracerVariants {
public:
    explicit TracerVariants(TracerEntry entry = TracerEntry::Fragment) : entry_(entry) {}

    // A new tracer of `variant`, given `scene` when not null so that a shader error surfaces now;
    // throws ShaderError.
    std::unique_ptr<PathTracer> compile(TracerVariant variant, const Scene* scene) const;
    // The cached tracer of `variant`, or null before keep().
    PathTracer* find(TracerVariant variant) const { return tracers_[int(variant)].get(); }
    PathTracer& keep(TracerVariant variant, std::unique_ptr<PathTracer> tracer);
    // Drops every cached tracer (after the shaders changed on disk).
    void clear();
    // Defines added to every variant from now on (a code-track exercise's slot); clear() to apply.
    void setExtraDefines(ShaderDefines defines) { extraDefines_ = std::move(defines); }
    const ShaderDefines& extraDefines() const { return extraDefines_; }

private:
    ShaderDefines extraDefines_;
    TracerEntry entry_;
    std::unique_ptr<PathTracer> tracers_[4];
};

} // namespace raylab
