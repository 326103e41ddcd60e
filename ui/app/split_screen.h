#pragma once
// The A/B split screen (classroom mode): the viewer's scene traced twice, each side with its own
// overrides (scene keys, as `--set` takes them), shown left (A) and right (B) of a divider, at
// equal samples or equal time (split_accounting.h). Each side is a PathTracer of its own, traced
// in whole passes on the same seed as raylab-render, so each half is exactly raylab-render's image
// of that side's settings. Both sides keep a convergence series (stats/convergence_series.h).
// Follows the viewer: any restart of its accumulation (an edit, a camera move) rebuilds both sides.
// Each side's tracer is compiled with the viewer's running defines (a code-track exercise's
// function) unless the side is given its own (the exercise's "yours against the reference"). A
// side may trace a debug view instead of the image (the override "debug-view", e.g. ao beside
// the render), as raylab-render --debug-view does.
// Needs a current GL 4.5 context once turned on.
#include "app/split_accounting.h"
#include "app/viewer.h"
#include "render/display_pass.h"
#include "render/path_tracer.h"
#include "stats/convergence_series.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raylab::ui {

class SplitScreen {
public:
    SplitScreen();
    ~SplitScreen();
    SplitScreen(const SplitScreen&) = delete;
    SplitScreen& operator=(const SplitScreen&) = delete;

    bool on() const { return on_; }
    void start(SplitBudget budget);   // on (overrides kept); restarts both sides
    // Starts afresh at equal samples with side A tracing view `a` and B `b` (ao beside the render).
    void startViews(DebugView a, DebugView b);
    void stop();                      // off: overrides cleared, tracers freed
    SplitBudget budget() const { return accounting_.budget(); }

    // An override for side 0 (A) or 1 (B), checked against `scene` (the viewer's): returns the
    // error ("" when it applies). A later override of the same key replaces the earlier one. The
    // key kViewKey takes a traced debug view's name (or beauty) instead of a scene key.
    static constexpr std::string_view kViewKey = "debug-view";
    std::string addOverride(int side, const std::string& key, const std::string& value, const Scene& scene);
    const std::vector<std::pair<std::string, std::string>>& overrides(int side) const { return overrides_[side & 1]; }
    std::string label(int side) const;   // "A: render.nee=false" (or "A: as the scene")
    DebugView view(int side) const { return views_[side & 1]; }   // what the side traces
    // Side 0 or 1 compiled with these defines instead of the viewer's; stop() forgets them.
    // `name` is what the side's label calls them ("your function", "the reference").
    void setDefines(int side, ShaderDefines defines, std::string name);
    float divider = 0.5f;                // 0 to 1 of the image width: A left of it, B right

    // Traces whole passes, side by side as the accounting says, for about budgetSeconds (at least
    // one pass) unless the viewer is paused or both sides are done.
    void update(Viewer& viewer, double budgetSeconds);
    // Done: equal samples, both sides at their render.spp; equal time, one side at its render.spp
    // or both past render.time (when set).
    bool converged() const;
    std::uint64_t minSpp() const;
    const SplitAccounting& accounting() const { return accounting_; }
    const stats::ConvergenceSeries& series(int side) const { return series_[side & 1]; }
    int rpp() const { return scenes_[0].render.rpp; }

    // The side's RGBA8 display texture (exposure and tone map of the viewer's scene), 0 when off.
    unsigned displayTexture(int side);
    Image image(int side) const;   // the side's linear image, top row first as Image expects
    Image composite() const;       // columns left of the divider from A, the rest from B
    bool exportComposite(const std::string& file, Viewer& viewer) const;
    const std::string& lastError() const { return lastError_; }

private:
    void rebuild(Viewer& viewer);
    bool on_ = false;
    bool dirty_ = true;
    std::uint64_t seenRestarts_ = ~std::uint64_t(0);
    std::vector<std::pair<std::string, std::string>> overrides_[2];
    DebugView views_[2] = {DebugView::Beauty, DebugView::Beauty};
    float depthScale_ = 1.0f;                    // the viewer's, for a depth side
    std::optional<ShaderDefines> defines_[2];   // none: the viewer's running defines
    std::string definesName_[2];
    ShaderDefines builtWith_[2];                 // the defines tracers_[i] was compiled with (its variant's too)
    Scene scenes_[2];
    std::unique_ptr<PathTracer> tracers_[2];
    SplitAccounting accounting_;
    stats::ConvergenceSeries series_[2];
    std::string lastError_;
    std::unique_ptr<DisplayPass> display_[2];   // created when first shown (needs GL)
    std::uint64_t shownSpp_[2] = {~std::uint64_t(0), ~std::uint64_t(0)};
};

} // namespace raylab::ui
