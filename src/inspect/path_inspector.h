#pragma once
// The pixel path inspector: records a chosen pixel's next sample paths with every term of the
// estimator (inspect/path_record.h). It runs its own tracer variant, compiled with
// RAYLAB_INSPECT_PATHS (shaders/include/path_record.glsl), over the pixel's row only; the
// samples are the very ones the normal tracer takes (same seed, same sample indices), so the
// recorded values are the contributions the pixel gets. Under a bounce filter (the viewer's
// bounce views) the values are those of that view, and each term says whether it counts. Needs a
// current GL 4.5 context.
#include "inspect/path_record.h"
#include "render/debug_views.h"
#include "render/path_tracer.h"
#include "scene/scene.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace raylab {

// Which bounces' light the recorded value keeps, as the viewer's bounce views do: all (the beauty
// estimator), bounce k only, direct (bounces 0 and 1), indirect (bounces 2 and more).
enum class BounceFilter {
    All = int(DebugView::Beauty),
    Only = int(DebugView::BounceK),
    Direct = int(DebugView::Direct),
    Indirect = int(DebugView::Indirect),
};

class PathInspector {
public:
    // Records at most maxRecords bounces a path (the rest are counted as truncated); extraDefines
    // are compiled in as into the traced image's tracer (a code-track exercise's file define), so
    // the paths are the ones that tracer takes.
    static constexpr int kDefaultMaxRecords = 64;
    explicit PathInspector(int maxRecords = kDefaultMaxRecords, ShaderDefines extraDefines = {});
    ~PathInspector();
    PathInspector(const PathInspector&) = delete;
    PathInspector& operator=(const PathInspector&) = delete;

    // Uploads the scene (as PathTracer::setScene); call again whenever the scene changes.
    void setScene(const Scene& scene);
    // Samples [firstSample, firstSample + count) of image pixel (x, y), top-left origin.
    // Throws std::out_of_range for a pixel outside the image, std::logic_error before setScene.
    std::vector<PathRecord> record(int x, int y, int count, std::uint64_t firstSample = 0);
    // Records the values a bounce view shows from now on (bounce: the k of BounceFilter::Only).
    void setBounceFilter(BounceFilter filter, int bounce = 0);
    BounceFilter bounceFilter() const { return filter_; }
    int filterBounce() const { return filterBounce_; }

    const PathTracer& tracer() const { return *tracer_; }
    int maxRecords() const { return maxRecords_; }
    const ShaderDefines& extraDefines() const { return extraDefines_; }
    // The defines that turn the recorder on, with the bounce views' filter (for tests that render
    // with the variant; it traces the beauty image until told another view).
    static TracerOptions inspectorOptions(ShaderDefines extraDefines = {});

private:
    ShaderDefines extraDefines_;
    std::unique_ptr<PathTracer> tracer_;
    int maxRecords_;
    BounceFilter filter_ = BounceFilter::All;
    int filterBounce_ = 0;
    bool hasScene_ = false;
    std::vector<Light> lights_;      // the scene's, to name the lights a sample picks
    unsigned buffers_[2] = {0, 0};   // bindings 20 (bounces) and 21 (paths)
    std::size_t capacity_ = 0;       // paths the buffers hold
};

} // namespace raylab
