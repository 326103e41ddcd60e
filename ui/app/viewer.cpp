#include "app/viewer.h"

#include "app/focus_pick.h"
#include "app/scene_object.h"
#include "app/view_geometry.h"
#include "io/image_io.h"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace raylab::ui {
namespace {

double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

} // namespace

Viewer::Viewer(Log& log) : log_(log) { reloadShaders(); }

Viewer::~Viewer() = default;

// --- files ---------------------------------------------------------------------------------------

bool Viewer::openScene(const std::filesystem::path& file) {
    if (!document_.open(file)) return false;
    selection.select(-1);
    return true;
}

void Viewer::pollFileChanges() {
    const int keep = selection.object(), keepMaterial = selection.material(), keepLight = selection.light();
    if (!document_.reloadIfChanged()) return;
    selection.select(-1);
    if (keep < objectCount(scene_)) selection.select(keep, keepMaterial);
    if (keepLight >= 0) selection.selectLight(keepLight);   // none when the light is gone
}

bool Viewer::exportRender(const std::filesystem::path& file) {
    if (!hasScene()) {
        log_.error("export: no scene");
        return false;
    }
    try {
        RenderMetadata meta;
        meta.spp = tracer_->samplesPerPixel();
        meta.renderSeconds = stats_.traceSeconds;
        meta.seed = scene_.render.seed;
        meta.sceneFile = document_.path().string();
        meta.nonFiniteSamples = tracer_->nonFiniteSamples();
        writeImage(file, tracer_->readImage(), meta, DisplayTransform{scene_.render.exposure, scene_.render.toneMap});
        log_.info("exported " + file.string() + " (" + std::to_string(meta.spp) + " spp)");
        return true;
    } catch (const std::exception& e) {
        document_.setError(e.what());
        log_.error(document_.lastError());
        return false;
    }
}

std::unique_ptr<PathTracer> Viewer::compileVariant(TracerVariant v) {
    // Given the scene now, so a shader error surfaces while the previous tracer still runs.
    const Scene scene = document_.loaded() ? tracedScene() : Scene{};
    auto tracer = variants_.compile(v, document_.loaded() ? &scene : nullptr);
    stats_.shaderCompileSeconds = tracer->compileSeconds();
    return tracer;
}

bool Viewer::activateVariant(TracerVariant v) {
    if (!variants_.find(v)) {
        try {
            const double t0 = now();
            variants_.keep(v, compileVariant(v));
            // A new variant stalls the UI for its compile: say how long (bench/viewer.md).
            char text[160];
            std::snprintf(text, sizeof text, "compiled the tracer for the %s view in %.2f s (shader %.2f s)",
                          std::string(debugViewName(view_)).c_str(), now() - t0, stats_.shaderCompileSeconds);
            log_.info(text);
        } catch (const std::exception& e) {
            document_.setError(e.what());
            log_.error(document_.lastError());
            return false;
        }
    }
    tracer_ = variants_.find(v);
    variant_ = v;
    slicer_.forgetCosts();   // another variant, another cost per sample
    if (document_.loaded()) {
        tracer_->setScene(tracedScene());
        restart();
    }
    return true;
}

bool Viewer::setTracerDefines(ShaderDefines defines) {
    variants_.setExtraDefines(std::move(defines));
    return reloadShaders();
}

bool Viewer::reloadShaders() {
    try {
        auto tracer = compileVariant(variant_);
        display_.reload();
        variants_.clear();   // the others recompile when next needed
        tracer_ = &variants_.keep(variant_, std::move(tracer));
    } catch (const std::exception& e) {
        document_.setError(e.what());
        log_.error(document_.lastError() + (tracer_ ? " (the previous shaders stay)" : ""));
        return false;
    }
    document_.clearError();
    runningDefines_ = variants_.extraDefines();
    slicer_.forgetCosts();   // new shaders, new costs
    if (document_.loaded()) {
        tracer_->setScene(tracedScene());
        restart();
    }
    return true;
}

// --- the scene reaching the tracer ----------------------------------------------------------------

bool Viewer::upload(const Scene& next, Trigger trigger) {
    // Another scene, other materials or objects elsewhere cost what they cost: the pass slicer
    // measures again (camera edits keep its costs: they come every frame of a drag).
    if (trigger != Trigger::ResetAccumulation) slicer_.forgetCosts();
    // ResetAccumulation keeps every scene buffer (camera, sky values, render settings: a camera
    // drag must not rebuild a million-triangle BVH each frame); MoveObjects rebuilds the top level
    // only (the meshes' BVHs stay); UpdateMaterials re-uploads the materials and the lights;
    // ReloadScene everything. Each reallocates only when the image size changed and recompiles
    // only for a feature set never met.
    const bool hasScene = document_.loaded();
    try {
        if (hasScene && trigger == Trigger::ResetAccumulation)
            tracer_->updateSettings(traced(next));
        else if (hasScene && trigger == Trigger::MoveObjects && next.spheres.size() == scene_.spheres.size() &&
                 next.meshes.size() == scene_.meshes.size())
            tracer_->updateTransforms(traced(next));
        else if (hasScene && trigger == Trigger::UpdateMaterials && next.materials.size() == scene_.materials.size())
            tracer_->updateMaterials(traced(next));
        else
            tracer_->setScene(traced(next));
    } catch (const std::exception& e) {
        document_.setError(e.what());
        log_.error(document_.lastError());
        if (hasScene) tracer_->setScene(tracedScene());   // put the previous scene back
        return false;
    }
    return true;
}

Scene Viewer::tracedScene() const { return traced(scene_); }

Scene Viewer::traced(Scene s) const {
    s.render.width = std::max(1, int(std::lround(float(s.render.width) * scale_)));
    s.render.height = std::max(1, int(std::lround(float(s.render.height) * scale_)));
    if (bounceStep_ > 0) s.render.maxBounces = std::min(s.render.maxBounces, bounceStep_);
    return s;
}

void Viewer::restart() {
    const int w = tracer_->width();
    const int h = tracer_->height();
    debug_.restart(w, h);
    setTracedView(tracer_->program(), view_, bounce_);
    slicer_.restart(w, h, scene_.render.rpp);
    stats_.traceSeconds = 0.0;
    passWall_ = 0.0;
    ++stats_.restarts;
    restartTime_ = now();
}

// --- render control ------------------------------------------------------------------------------

void Viewer::resetAccumulation() {
    if (!hasScene()) return;
    tracer_->reset();
    restart();
}

void Viewer::setResolutionScale(float scale) {
    scale = std::clamp(scale, 0.125f, 2.0f);
    if (scale == scale_) return;
    scale_ = scale;
    if (hasScene()) document_.changed(Trigger::ReloadScene);
}

void Viewer::setDebugView(DebugView view) {
    if (view == view_) return;
    const DebugView previous = view_;
    view_ = view;
    if (!tracer_) return;
    const TracerVariant v = variantFor(view);
    if (v != variant_) {
        if (!activateVariant(v)) {
            view_ = previous;   // the variant did not compile: stay with what works
            return;
        }
    } else if (v == TracerVariant::Views) {
        slicer_.forgetCosts();   // a normal costs one ray, a bounce view a path
        resetAccumulation();     // another quantity accumulates
    } else {
        displayDirty_ = true;  // same samples, drawn differently
    }
}

void Viewer::setDebugBounce(int k) {
    k = std::max(k, 0);
    if (k == bounce_) return;
    bounce_ = k;
    if (view_ == DebugView::BounceK) resetAccumulation();
}

void Viewer::setBounceStep(int k) {
    k = std::max(k, 0);
    if (k == bounceStep_) return;
    bounceStep_ = k;
    slicer_.forgetCosts();   // another path length
    if (hasScene()) document_.changed(Trigger::ResetAccumulation);
}

int Viewer::imageWidth() const { return std::max(1, int(std::lround(float(scene_.render.width) * scale_))); }
int Viewer::imageHeight() const { return std::max(1, int(std::lround(float(scene_.render.height) * scale_))); }

bool Viewer::converged() const {
    if (!hasScene()) return true;
    if (tracer_->samplesPerPixel() >= std::uint64_t(scene_.render.spp)) return true;
    // The time budget stops between passes, after the pass that crosses it (as raylab-render):
    // stopped mid-pass, the rows already traced would hold more samples than the others.
    return scene_.render.timeBudget > 0.0 && stats_.traceSeconds >= scene_.render.timeBudget && !slicer_.midPass();
}

void Viewer::update(double budgetSeconds) {
    stats_.frameTraceMs = 0.0;
    if (!hasScene() || paused_ || converged()) return;
    const double start = now();
    debug_.bind();
    do {
        // The last pass before the target is shortened to land on it exactly (as raylab-render).
        const std::uint64_t left = std::uint64_t(scene_.render.spp) - tracer_->samplesPerPixel();
        if (!slicer_.midPass() && left < std::uint64_t(scene_.render.rpp))
            slicer_.restart(tracer_->width(), tracer_->height(), int(left));
        const double spent = now() - start;
        const WorkUnit u = slicer_.next(std::max(budgetSeconds - spent, budgetSeconds * 0.25));
        const double t0 = now();
        tracer_->traceBand(u.y, u.rows, u.sampleOffset, u.rpp);
        const double dt = now() - t0;
        slicer_.measured(u, dt);
        stats_.traceSeconds += dt;
        passWall_ += dt;
        if (u.endsPass) {
            tracer_->finishPass(u.passRpp);
            stats_.lastPassMs = passWall_ * 1e3;
            passWall_ = 0.0;
            if (slicer_.midPass() == false && u.passRpp != scene_.render.rpp)
                slicer_.restart(tracer_->width(), tracer_->height(), scene_.render.rpp);
            break;   // a complete pass: let the display show it before tracing on
        }
    } while (now() - start < budgetSeconds);
    stats_.frameTraceMs = (now() - start) * 1e3;
    tracedSinceDisplay_ = true;
}

bool Viewer::needsDisplay() const {
    if (!hasScene()) return false;
    if (displayDirty_ || !display_.texture() || display_.width() != tracer_->width() ||
        display_.height() != tracer_->height())
        return true;
    if (!tracedSinceDisplay_) return false;
    const double t = now();
    const bool firstPassPending = tracer_->samplesPerPixel() == 0 && t - restartTime_ < 0.25;
    const bool passDone = !slicer_.midPass();
    return paused_ || (!firstPassPending && (passDone || t - lastDisplay_ > 0.25));
}

unsigned Viewer::displayTexture() {
    stats_.frameDisplayMs = 0.0;
    if (!hasScene()) return 0;
    const double t0 = now();
    if (!needsDisplay()) return display_.texture();
    DisplayParams p = displayParams(tracer_->width(), tracer_->height(), view_,
                                    DisplayTransform{scene_.render.exposure, scene_.render.toneMap});
    p.depthScale = depthScale;
    p.noiseScale = noiseScale;
    p.spp = float(tracer_->samplesPerPixel());
    p.hasMoments = variant_ == TracerVariant::Moments && tracer_->samplesPerPixel() > 0 ? 1 : 0;
    const unsigned source =
        view_ == DebugView::Samples ? sampleCounts_.update(*tracer_) : tracer_->accumulationTexture();
    p.heatScale = heatScaleInUse();
    display_.draw(source, p, debug_.moments());
    glFinish();   // so the time below is the pass's (llvmpipe runs it at the flush)
    stats_.displayMs = (now() - t0) * 1e3;
    stats_.frameDisplayMs = stats_.displayMs;
    displayDirty_ = false;
    tracedSinceDisplay_ = false;
    lastDisplay_ = now();
    return display_.texture();
}

glm::vec4 Viewer::pixelValue(int x, int y) const {
    glm::vec4 v(0.0f);
    if (!hasScene() || x < 0 || y < 0 || x >= tracer_->width() || y >= tracer_->height()) return v;
    glGetTextureSubImage(tracer_->accumulationTexture(), 0, x, tracer_->height() - 1 - y, 0, 1, 1, 1, GL_RGBA,
                         GL_FLOAT, sizeof(v), &v[0]);
    return v;
}

std::optional<int> Viewer::pick(float x, float y) {
    if (!hasScene()) return std::nullopt;
    return selection.pick(*geometry(), imageWidth(), imageHeight(), ImagePoint{x, y}, log_);
}

std::optional<float> Viewer::focusAt(float x, float y) {
    if (!hasScene()) return std::nullopt;
    const std::optional<float> d = focusDistanceAt(scene_, *geometry(), imageWidth(), imageHeight(), ImagePoint{x, y});
    if (!d) {
        log_.info("focus: nothing at (" + std::to_string(int(x)) + ", " + std::to_string(int(y)) + ") (sky)");
        return std::nullopt;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(*d));
    if (!document_.set("camera.focus_distance", text)) return std::nullopt;
    log_.info(std::string("focus distance ") + text + " (the surface at image pixel (" + std::to_string(int(x)) + ", " +
              std::to_string(int(y)) + "))");
    return d;
}

float Viewer::heatScaleInUse() const {
    if (!heatScaleAuto) return std::max(heatScale, 1e-3f);
    if (view_ == DebugView::Samples) return float(std::max<std::uint64_t>(1, sampleCounts_.largest()));
    const glm::uvec2 max = variant_ == TracerVariant::Counts ? debug_.heatMax() : glm::uvec2(0);
    return float(std::max(1u, view_ == DebugView::Triangles ? max.y : max.x));
}

std::string Viewer::shaderVariant() const {
    return tracer_ ? tracer_->variantName() + std::string(variantSuffix(variant_)) : "none (shader error)";
}

} // namespace raylab::ui
