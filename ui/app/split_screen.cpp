#include "app/split_screen.h"

#include "io/image_io.h"
#include "render/debug_buffers.h"
#include "render/tracer_variants.h"
#include "scene/parameters.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace raylab::ui {
namespace {

double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// A side's debug view, or the complaint: the split traces the views traced in place of the beauty
// path (the moments and the heat maps need the viewer's buffers).
std::optional<DebugView> sideView(const std::string& name, std::string& error) {
    const std::optional<DebugView> view = parseDebugView(name);
    if (view && (*view == DebugView::Beauty || (tracedDebugView(*view) && !heatMapView(*view)))) return view;
    std::string names;
    for (DebugView v : kDebugViews)
        if (v == DebugView::Beauty || (tracedDebugView(v) && !heatMapView(v)))
            names += (names.empty() ? "" : ", ") + std::string(debugViewName(v));
    error = "'" + name + "' is not a view a side can trace (" + names + ")";
    return std::nullopt;
}

} // namespace

SplitScreen::SplitScreen() = default;
SplitScreen::~SplitScreen() = default;

void SplitScreen::start(SplitBudget budget) {
    on_ = true;
    dirty_ = true;
    accounting_.reset(budget);
}

void SplitScreen::startViews(DebugView a, DebugView b) {
    stop();
    const DebugView views[2] = {a, b};
    for (int i = 0; i < 2; ++i) {
        views_[i] = views[i];
        if (views[i] != DebugView::Beauty) overrides_[i].emplace_back(kViewKey, debugViewName(views[i]));
    }
    start(SplitBudget::EqualSamples);
}

void SplitScreen::stop() {
    on_ = false;
    for (int i = 0; i < 2; ++i) {
        overrides_[i].clear();
        views_[i] = DebugView::Beauty;
        defines_[i].reset();
        definesName_[i].clear();
    }
    tracers_[0].reset();
    tracers_[1].reset();
    dirty_ = true;
}

std::string SplitScreen::addOverride(int side, const std::string& key, const std::string& value, const Scene& scene) {
    if (key == kViewKey) {
        std::string error;
        const std::optional<DebugView> view = sideView(value, error);
        if (!view) return error;
        views_[side & 1] = *view;
    } else {
        Scene probe = scene;
        try {
            for (const auto& [k, v] : overrides_[side & 1])
                if (k != kViewKey) setParam(probe, k, v);
            setParam(probe, key, value);
        } catch (const std::exception& e) {
            return e.what();
        }
    }
    auto& list = overrides_[side & 1];
    std::erase_if(list, [&](const auto& kv) { return kv.first == key; });
    list.emplace_back(key, value);
    dirty_ = true;
    return "";
}

void SplitScreen::setDefines(int side, ShaderDefines defines, std::string name) {
    defines_[side & 1] = std::move(defines);
    definesName_[side & 1] = std::move(name);
    dirty_ = true;
}

std::string SplitScreen::label(int side) const {
    std::string s = side == 0 ? "A" : "B";
    const auto& list = overrides_[side & 1];
    const std::string& name = definesName_[side & 1];
    if (list.empty()) return s + ": " + (name.empty() ? "as the scene" : name);
    s += ":";
    if (!name.empty()) s += " " + name + ",";
    for (const auto& [k, v] : list) s += " " + k + "=" + v;
    return s;
}

void SplitScreen::rebuild(Viewer& viewer) {
    seenRestarts_ = viewer.stats().restarts;
    depthScale_ = viewer.depthScale;
    dirty_ = false;
    accounting_.reset(accounting_.budget());
    lastError_.clear();
    for (int i = 0; i < 2; ++i) {
        series_[i].reset();
        shownSpp_[i] = ~std::uint64_t(0);
        Scene s = viewer.scene();
        s.render.width = viewer.imageWidth();
        s.render.height = viewer.imageHeight();
        try {
            for (const auto& [k, v] : overrides_[i])
                if (k != kViewKey) setParam(s, k, v);
            TracerOptions options = variantOptions(variantFor(views_[i]), TracerEntry::Fragment);
            const ShaderDefines& own = defines_[i] ? *defines_[i] : viewer.runningTracerDefines();
            options.extraDefines.insert(options.extraDefines.end(), own.begin(), own.end());
            const bool fresh = !tracers_[i] || builtWith_[i] != options.extraDefines;
            if (fresh) {
                builtWith_[i] = options.extraDefines;
                tracers_[i] = std::make_unique<PathTracer>(std::move(options));
            }
            const std::string variant = tracers_[i]->variantName();
            tracers_[i]->setScene(s);
            if (views_[i] != DebugView::Beauty) setTracedView(tracers_[i]->program(), views_[i], viewer.debugBounce());
            if (fresh || tracers_[i]->variantName() != variant) {
                // A new program's first draw includes the driver's compile (llvmpipe JITs it):
                // one untimed pass, dropped, so equal time compares tracing, not compiling.
                tracers_[i]->renderPass(1);
                tracers_[i]->reset();
            }
        } catch (const std::exception& e) {
            lastError_ = e.what();
            viewer.log().error("split screen: " + lastError_);
            tracers_[i].reset();
        }
        scenes_[i] = std::move(s);
    }
}

bool SplitScreen::converged() const {
    if (!on_) return true;
    if (dirty_) return false;   // not traced yet: update() builds both sides first
    if (!tracers_[0] || !tracers_[1]) return true;   // a side failed to build (the error is logged)
    const auto done = [&](int i) { return accounting_.side(i).spp >= std::uint64_t(scenes_[i].render.spp); };
    if (accounting_.budget() == SplitBudget::EqualSamples) return done(0) && done(1);
    const double t = scenes_[0].render.timeBudget;
    return done(0) || done(1) || (t > 0.0 && accounting_.side(0).seconds >= t && accounting_.side(1).seconds >= t);
}

std::uint64_t SplitScreen::minSpp() const { return std::min(accounting_.side(0).spp, accounting_.side(1).spp); }

void SplitScreen::update(Viewer& viewer, double budgetSeconds) {
    if (!on_ || !viewer.hasScene()) return;
    if (dirty_ || viewer.stats().restarts != seenRestarts_) rebuild(viewer);
    if (viewer.paused()) return;
    const double start = now();
    while (!converged()) {
        const int side = accounting_.next();
        // Equal samples: the last pass lands on the target exactly (as raylab-render's).
        const std::uint64_t left = std::uint64_t(scenes_[side].render.spp) - accounting_.side(side).spp;
        const int rpp = int(std::min<std::uint64_t>(std::uint64_t(scenes_[side].render.rpp), left));
        const double t0 = now();
        tracers_[side]->renderPass(rpp);   // waits for the pass
        accounting_.record(side, rpp, now() - t0);
        const SplitSide& s = accounting_.side(side);
        if (series_[side].wants(s.spp)) series_[side].add(s.spp, s.seconds, tracers_[side]->readImage());
        if (now() - start >= budgetSeconds) break;
    }
}

unsigned SplitScreen::displayTexture(int side) {
    side &= 1;
    if (!on_ || !tracers_[side]) return 0;
    if (!display_[side]) display_[side] = std::make_unique<DisplayPass>();
    DisplayPass& pass = *display_[side];
    const int w = tracers_[side]->width(), h = tracers_[side]->height();
    if (pass.width() != w || pass.height() != h) shownSpp_[side] = ~std::uint64_t(0);
    const std::uint64_t spp = accounting_.side(side).spp;
    if (spp == shownSpp_[side]) return pass.texture();
    const Scene& s = scenes_[side];
    DisplayParams p = displayParams(w, h, views_[side], DisplayTransform{s.render.exposure, s.render.toneMap});
    p.spp = float(spp);
    p.depthScale = depthScale_;
    pass.draw(tracers_[side]->accumulationTexture(), p);
    shownSpp_[side] = spp;
    return pass.texture();
}

Image SplitScreen::image(int side) const {
    return tracers_[side & 1] ? tracers_[side & 1]->readImage() : Image{};
}

Image SplitScreen::composite() const {
    Image a = image(0);
    const Image b = image(1);
    if (a.rgba.empty() || b.rgba.size() != a.rgba.size()) return Image{};
    const int split = int(std::lround(divider * float(a.width)));
    for (int y = 0; y < a.height; ++y)
        for (int x = std::max(split, 0); x < a.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const std::size_t i = (std::size_t(y) * std::size_t(a.width) + std::size_t(x)) * 4 + std::size_t(c);
                a.rgba[i] = b.rgba[i];
            }
    return a;
}

bool SplitScreen::exportComposite(const std::string& file, Viewer& viewer) const {
    try {
        const Image img = composite();
        if (img.rgba.empty()) throw std::runtime_error("split screen: nothing traced yet");
        RenderMetadata meta;
        meta.spp = minSpp();
        meta.renderSeconds = accounting_.side(0).seconds + accounting_.side(1).seconds;
        meta.seed = scenes_[0].render.seed;
        meta.sceneFile = viewer.document().path().string();
        writeImage(file, img, meta, DisplayTransform{scenes_[0].render.exposure, scenes_[0].render.toneMap});
        viewer.log().info("exported the split screen " + file + " (" + label(0) + " | " + label(1) + ")");
        return true;
    } catch (const std::exception& e) {
        viewer.log().error(e.what());
        return false;
    }
}

} // namespace raylab::ui
