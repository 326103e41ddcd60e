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


int toneMapOp(ToneMap t) {
    switch (t) {
    case ToneMap::Clamp: return 0;
    case ToneMap::Reinhard: return 1;
    case ToneMap::AcesFit: return 2;
    }
    return 2;
}

} // namespace

Viewer::Viewer(Log& log) : log_(log) {
    glCreateVertexArrays(1, &displayVao_);
    glCreateFramebuffers(1, &displayFramebuffer_);
    glCreateBuffers(1, &heatMaxBuffer_);
    glNamedBufferStorage(heatMaxBuffer_, 2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
    reloadShaders();
}

Viewer::~Viewer() {
    glDeleteBuffers(1, &momentsBuffer_);
    glDeleteBuffers(1, &heatMaxBuffer_);
    glDeleteTextures(1, &displayTexture_);
    glDeleteFramebuffers(1, &displayFramebuffer_);
    glDeleteVertexArrays(1, &displayVao_);
}

// --- files ---------------------------------------------------------------------------------------

bool Viewer::openScene(const std::filesystem::path& file) {
    if (!document_.open(file)) return false;
    selection.select(-1);
    return true;
}

void Viewer::pollFileChanges() {
    const int keep = selection.object(), keepMaterial = selection.material();
    if (!document_.reloadIfChanged()) return;
    selection.select(-1);
    if (keep < objectCount(scene_)) selection.select(keep, keepMaterial);
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

Viewer::Variant Viewer::variantFor(DebugView view) {
    if (heatMapView(view)) return kCounts;
    if (tracedDebugView(view)) return kViews;
    if (view == DebugView::NonFinite || view == DebugView::Noise) return kMoments;
    return kBeauty;
}

std::unique_ptr<PathTracer> Viewer::compileVariant(Variant v) {
    TracerOptions o;
    o.entry = TracerEntry::Fragment;   // bands need the scissor of the fragment entry
    if (v == kMoments) o.extraDefines.emplace_back(tracerDefine("RAYLAB_DEBUG_MOMENTS"), "1");
    if (v == kViews || v == kCounts) o.extraDefines.emplace_back(tracerDefine("RAYLAB_DEBUG_VIEWS"), "1");
    if (v == kCounts) o.extraDefines.emplace_back(tracerDefine("RAYLAB_COUNT_TRAVERSAL"), "1");
    auto tracer = std::make_unique<PathTracer>(o);
    // The tracer compiles its program for a scene's features: do it here, so a shader error
    // surfaces while the previous tracer still runs.
    if (document_.loaded()) tracer->setScene(tracedScene());
    stats_.shaderCompileSeconds = tracer->compileSeconds();
    return tracer;
}

bool Viewer::activateVariant(Variant v) {
    if (!tracers_[v]) {
        try {
            const double t0 = now();
            tracers_[v] = compileVariant(v);
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
    tracer_ = tracers_[v].get();
    variant_ = v;
    slicer_.forgetCosts();   // another variant, another cost per sample
    if (document_.loaded()) {
        tracer_->setScene(tracedScene());
        restart();
    }
    return true;
}

bool Viewer::reloadShaders() {
    try {
        auto tracer = compileVariant(variant_);
        ShaderProgram display = ShaderProgram::graphics("entry/fullscreen.vert", "entry/display.frag");
        for (auto& t : tracers_) t.reset();   // the others recompile when next needed
        tracers_[variant_] = std::move(tracer);
        tracer_ = tracers_[variant_].get();
        display_ = std::move(display);
    } catch (const std::exception& e) {
        document_.setError(e.what());
        log_.error(document_.lastError() + (tracer_ ? " (the previous shaders stay)" : ""));
        return false;
    }
    document_.clearError();
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
    const GLsizeiptr bytes = GLsizeiptr(w) * h * 16;
    GLint64 have = 0;
    if (momentsBuffer_) glGetNamedBufferParameteri64v(momentsBuffer_, GL_BUFFER_SIZE, &have);
    if (!momentsBuffer_ || have != bytes) {
        glDeleteBuffers(1, &momentsBuffer_);
        glCreateBuffers(1, &momentsBuffer_);
        glNamedBufferStorage(momentsBuffer_, bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    const float zero = 0.0f;
    glClearNamedBufferData(momentsBuffer_, GL_R32F, GL_RED, GL_FLOAT, &zero);
    const GLuint none = 0;
    glClearNamedBufferData(heatMaxBuffer_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    tracer_->program().set("uDebugView", int(view_));
    tracer_->program().set("uDebugBounce", bounce_);
    // texelFetch in the display pass needs a complete texture: one level, no mipmap filter.
    glTextureParameteri(tracer_->accumulationTexture(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(tracer_->accumulationTexture(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
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
    const Variant v = variantFor(view);
    if (v != variant_) {
        if (!activateVariant(v)) {
            view_ = previous;   // the variant did not compile: stay with what works
            return;
        }
    } else if (v == kViews) {
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
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 16, momentsBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 17, heatMaxBuffer_);
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

void Viewer::ensureDisplayTargets() {
    const int w = tracer_->width();
    const int h = tracer_->height();
    if (displayTexture_ && w == displayWidth_ && h == displayHeight_) return;
    glDeleteTextures(1, &displayTexture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &displayTexture_);
    glTextureStorage2D(displayTexture_, 1, GL_RGBA8, w, h);
    glTextureParameteri(displayTexture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(displayTexture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glNamedFramebufferTexture(displayFramebuffer_, GL_COLOR_ATTACHMENT0, displayTexture_, 0);
    displayWidth_ = w;
    displayHeight_ = h;
    displayDirty_ = true;
}

bool Viewer::needsDisplay() const {
    if (!hasScene()) return false;
    if (displayDirty_ || !displayTexture_) return true;
    if (!tracedSinceDisplay_) return false;
    const double t = now();
    const bool firstPassPending = tracer_->samplesPerPixel() == 0 && t - restartTime_ < 0.25;
    const bool passDone = !slicer_.midPass();
    return paused_ || (!firstPassPending && (passDone || t - lastDisplay_ > 0.25));
}

unsigned Viewer::displayTexture() {
    stats_.frameDisplayMs = 0.0;
    if (!hasScene()) return 0;
    ensureDisplayTargets();
    const double t0 = now();
    if (!needsDisplay()) return displayTexture_;
    const ShaderProgram& p = display_;
    p.set("uImageSize", glm::ivec2(displayWidth_, displayHeight_));
    p.set("uView", int(view_));
    p.set("uExposure", scene_.render.exposure);
    p.set("uToneMap", toneMapOp(scene_.render.toneMap));
    p.set("uDepthScale", depthScale);
    p.set("uNoiseScale", noiseScale);
    p.set("uSpp", float(tracer_->samplesPerPixel()));
    p.set("uHasMoments", variant_ == kMoments && tracer_->samplesPerPixel() > 0 ? 1 : 0);
    p.set("uHeatScale", heatScaleInUse());
    glBindFramebuffer(GL_FRAMEBUFFER, displayFramebuffer_);
    glViewport(0, 0, displayWidth_, displayHeight_);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glBindTextureUnit(0, tracer_->accumulationTexture());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 16, momentsBuffer_);
    glUseProgram(p.id());
    glBindVertexArray(displayVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glFinish();   // so the time below is the pass's (llvmpipe runs it at the flush)
    stats_.displayMs = (now() - t0) * 1e3;
    stats_.frameDisplayMs = stats_.displayMs;
    displayDirty_ = false;
    tracedSinceDisplay_ = false;
    lastDisplay_ = now();
    return displayTexture_;
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
    GLuint max[2] = {0, 0};
    if (variant_ == kCounts) glGetNamedBufferSubData(heatMaxBuffer_, 0, sizeof(max), max);
    return float(std::max(1u, view_ == DebugView::Triangles ? max[1] : max[0]));
}

std::string Viewer::shaderVariant() const {
    static const char* const extra[] = {"", " + moments", " + debug views", " + debug views + traversal counts"};
    return tracer_ ? tracer_->variantName() + extra[variant_] : "none (shader error)";
}

} // namespace raylab::ui
