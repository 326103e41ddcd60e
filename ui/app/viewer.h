#pragma once
// The viewer's model and its render session: it composes the scene document (app/scene_document.h:
// files, edits, the last error) and the selection (app/selection.h), and itself runs the path
// tracer on the document's scene (the same renderer core as raylab-render): the time-sliced
// progressive passes, the display pass, the overlays and the stats. No window and no ImGui here:
// the views in ui/panels read and change this object. Needs a current GL 4.5 context.
#include "app/brdf_explorer_model.h"
#include "app/debug_view.h"
#include "app/inspection.h"
#include "app/log.h"
#include "app/pass_slicer.h"
#include "app/scene_document.h"
#include "app/selection.h"
#include "render/debug_buffers.h"
#include "render/display_pass.h"
#include "render/path_tracer.h"
#include "render/sample_count_texture.h"
#include "render/tracer_variants.h"
#include "scene/scene.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace raylab::ui {

struct ViewerStats {
    double traceSeconds = 0.0;       // GPU tracing time since accumulation restarted
    double lastPassMs = 0.0;         // wall time of the last complete pass (all its slices)
    double frameTraceMs = 0.0;       // tracing time spent in the last UI frame
    double displayMs = 0.0;          // the last display pass
    double frameDisplayMs = 0.0;     // the display pass in the last UI frame (0 when not needed)
    double shaderCompileSeconds = 0.0;
    std::uint64_t restarts = 0;      // times accumulation restarted
};

struct OverlaySettings {
    bool boxes = false;          // every object's bounding box
    bool selectedOnly = false;   // only the selected object's box
    bool bvh = false;            // the top-level BVH's nodes at bvhDepth (app/bvh_overlay.h)
    bool meshBvh = false;        // the meshes' BVH nodes at bvhDepth
    int bvhDepth = 0;            // 0 = the root
    bool lights = false;         // a gizmo per light (app/light_gizmo.h)
};

class Viewer : private SceneRenderer {
    Log& log_;
    SceneDocument document_{log_, *this};   // first: the members below refer to it

public:
    explicit Viewer(Log& log);
    ~Viewer() override;
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    // --- the scene -------------------------------------------------------------------------------
    SceneDocument& document() { return document_; }
    const SceneDocument& document() const { return document_; }
    Scene& scene() { return document_.scene(); }   // the document's scene, which this session traces
    const Scene& scene() const { return document_.scene(); }
    // document().open() that also clears the selection.
    bool openScene(const std::filesystem::path& file);
    // Reloads when the file changed on disk, keeping the selection when it still exists; call once
    // a frame.
    void pollFileChanges();
    // The traced image as EXR (linear) or PNG (exposure and tone map applied).
    bool exportRender(const std::filesystem::path& file);
    bool reloadShaders() override;
    // Compiles the tracer with these defines added (a code-track exercise's file define; empty:
    // the reference); on a compile error the previous tracer keeps running. False on an error.
    bool setTracerDefines(ShaderDefines defines);
    // The defines the running tracer was compiled with (the last that compiled), which the path
    // inspector compiles in too so that it records the paths of the image on screen.
    const ShaderDefines& runningTracerDefines() const { return runningDefines_; }
    Scene tracedScene() const;   // the scene with the resolution scale applied (what the tracer traces)
    bool hasScene() const { return document_.loaded() && tracer_ != nullptr; }

    // --- render control ----------------------------------------------------------------------------
    void setPaused(bool paused) { paused_ = paused; }
    bool paused() const { return paused_; }
    void resetAccumulation();
    void setResolutionScale(float scale);   // clamped to [0.125, 2]
    float resolutionScale() const { return scale_; }
    void setDebugView(DebugView view);
    DebugView debugView() const { return view_; }
    void setDebugBounce(int k);   // the k of DebugView::BounceK, >= 0
    int debugBounce() const { return bounce_; }
    // Bounce stepping (teaching): k > 0 traces with render.max_bounces capped at k, so the image
    // holds the light of bounce views 0..k (0: emitters and sky seen directly); 0 = off. The
    // scene's own max_bounces is untouched (saving the scene does not save the cap).
    void setBounceStep(int k);
    int bounceStep() const { return bounceStep_; }
    float depthScale = 20.0f;   // depth view: distance shown black
    float noiseScale = 0.2f;    // noise view: relative error shown red
    bool heatScaleAuto = true;  // heat maps: red at the largest count of one camera ray so far
    float heatScale = 64.0f;    // heat maps: the count shown red when not automatic
    // The count the heat map shows as full red now (automatic: the largest of one ray since the
    // restart, read from the tracer, or in the samples view the most samples a pixel holds; at least 1).
    float heatScaleInUse() const;
    OverlaySettings overlays;
    float cameraSpeed = 2.0f;   // world units per second for WASD/QE
    Selection selection{document_.scene()};   // app/selection.h
    Inspection inspection;      // the pixel path inspector (app/inspection.h)
    BrdfExplorerModel brdfExplorer;   // the BRDF explorer (app/brdf_explorer_model.h)

    // The traced image size (the scene's render size × resolution scale).
    int imageWidth() const;
    int imageHeight() const;
    // Finished: target spp reached, or the time budget spent and the pass that crossed it complete.
    bool converged() const;
    // Traces slices of passes for about budgetSeconds (at least one slice unless paused/converged).
    void update(double budgetSeconds);
    // Runs the display pass when there is something new to show; returns the RGBA8 texture to show.
    // New samples are shown when a pass completes (or every 0.25 s during long passes, or at once
    // when paused); after a restart the previous picture stays until the first pass is complete,
    // so moving the camera never flashes a half-traced image.
    unsigned displayTexture();
    void redisplay() override { displayDirty_ = true; }   // after changing depthScale, noiseScale or the heat scale
    bool needsDisplay() const;   // the next displayTexture() would show something new
    // The linear value of image pixel (x, y), top-left origin, as accumulated.
    glm::vec4 pixelValue(int x, int y) const;
    // selection.pick() at image pixel (x, y) of the traced image.
    std::optional<int> pick(float x, float y);
    // Click-to-focus at image pixel (x, y): camera.focus_distance becomes the depth of the surface
    // there along the view axis (app/focus_pick.h); logs it. nullopt (and no change) for the sky.
    std::optional<float> focusAt(float x, float y);
    // The geometry the tracer traverses (BVHs for the overlays, CPU traversal), or null.
    const SceneGeometry* geometry() const { return tracer_ ? &tracer_->gpuScene().geometry() : nullptr; }

    // --- counters ----------------------------------------------------------------------------------
    const PathTracer* tracer() const { return tracer_; }
    const ViewerStats& stats() const { return stats_; }
    std::string shaderVariant() const;
    Log& log() { return log_; }

private:
    Scene traced(Scene s) const;  // s with the resolution scale and the bounce step applied
    bool ready() const override { return tracer_ != nullptr; }
    bool upload(const Scene& next, Trigger trigger) override;
    void restart() override;   // after a scene upload: clear moments, restart the slicer

    const Scene& scene_ = document_.scene();   // what the tracer traces
    std::unique_ptr<PathTracer> compileVariant(TracerVariant v);   // throws ShaderError
    bool activateVariant(TracerVariant v);
    ShaderDefines runningDefines_;
    TracerVariants variants_;   // the fragment entry (bands need its scissor), compiled when a view first needs one
    PathTracer* tracer_ = nullptr;
    TracerVariant variant_ = TracerVariant::Beauty;
    DebugBuffers debug_;
    DisplayPass display_;
    SampleCountTexture sampleCounts_;   // the samples view's image, updated when it is displayed
    PassSlicer slicer_;
    bool paused_ = false;
    float scale_ = 1.0f;
    DebugView view_ = DebugView::Beauty;
    int bounce_ = 1;
    int bounceStep_ = 0;
    ViewerStats stats_;
    double passWall_ = 0.0;

    bool displayDirty_ = true;        // display settings or targets changed: show at once
    bool tracedSinceDisplay_ = false; // samples traced that the display texture does not show yet
    double lastDisplay_ = 0.0;        // when the display pass last ran (seconds)
    double restartTime_ = 0.0;        // when accumulation last restarted
};

} // namespace raylab::ui
