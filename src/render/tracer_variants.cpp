#include "render/tracer_variants.h"

namespace raylab {

TracerVariant variantFor(DebugView view) {
    const DebugViewInfo& v = debugViewInfo(view);
    if (v.countsTraversal) return TracerVariant::Counts;
    if (v.traced) return TracerVariant::Views;
    if (v.moments) return TracerVariant::Moments;
    return TracerVariant::Beauty;
}

TracerOptions variantOptions(TracerVariant variant, TracerEntry entry) {
    TracerOptions o;
    o.entry = entry;
    if (variant == TracerVariant::Moments) o.extraDefines.emplace_back(tracerDefine("RAYLAB_DEBUG_MOMENTS"), "1");
    if (variant == TracerVariant::Views || variant == TracerVariant::Counts)
        o.extraDefines.emplace_back(tracerDefine("RAYLAB_DEBUG_VIEWS"), "1");
    if (variant == TracerVariant::Counts) o.extraDefines.emplace_back(tracerDefine("RAYLAB_COUNT_TRAVERSAL"), "1");
    return o;
}

std::string_view variantSuffix(TracerVariant variant) {
    switch (variant) {
    case TracerVariant::Beauty: return "";
    case TracerVariant::Moments: return " + moments";
    case TracerVariant::Views: return " + debug views";
    case TracerVariant::Counts: return " + debug views + traversal counts";
    }
    return "";
}

std::unique_ptr<PathTracer> TracerVariants::compile(TracerVariant variant, const Scene* scene) const {
    TracerOptions o = variantOptions(variant, entry_);
    o.extraDefines.insert(o.extraDefines.end(), extraDefines_.begin(), extraDefines_.end());
    auto tracer = std::make_unique<PathTracer>(o);
    // The tracer compiles its program for a scene's features.
    if (scene) tracer->setScene(*scene);
    return tracer;
}

PathTracer& TracerVariants::keep(TracerVariant variant, std::unique_ptr<PathTracer> tracer) {
    tracers_[int(variant)] = std::move(tracer);
    return *tracers_[int(variant)];
}

void TracerVariants::clear() {
    for (auto& t : tracers_) t.reset();
}

} // namespace raylab
