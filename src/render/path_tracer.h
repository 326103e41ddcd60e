#pragma once
// The GPU path tracer: owns the accumulation image, the scene buffers and the tracer program.
// One pass adds rpp samples per pixel to a running mean (float32 RGBA). Needs a current GL 4.5
// context (see gl/gl_context.h). Both programs, the headless CLI and the viewer, drive this class.
#include "gl/shader_program.h"
#include "render/adaptive_sampling.h"
#include "render/gpu_scene.h"
#include "render/image.h"
#include "render/shader_variant.h"
#include "render/tracer_defines.h"
#include "scene/scene.h"
#include "shaders/include/tracer_params.glsl"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

// Which entry point runs the tracer; the fragment entry is the faster on llvmpipe (bench/throughput.md).
enum class TracerEntry { Fragment, Compute };

struct TracerOptions {
    TracerEntry entry = TracerEntry::Fragment;
    int localSizeX = 8;   // compute only
    int localSizeY = 8;   // compute only
    ShaderDefines extraDefines;   // names from kTracerDefines (tracer_defines.h), e.g. RAYLAB_DEBUG_VIEWS
    bool specialise = true;       // compile for the scene's features (false: all features on)
    bool cameraRelative = true;   // upload positions relative to the camera (false: world, for tests)
    bool balanceTiles = true;     // fragment only: draw a small image as a strip, an adaptive round as the strip of its blocks (fragment_layout.glsl)
};

// The strip (fragment_layout.glsl) in which the fragment entry draws a width × height image for
// `threads` rasteriser threads, as its number of tiles: 0 (none) from 4 tiles per thread on,
// where llvmpipe's queue of tiles balances itself; else one tile per thread.
int fragmentStripTiles(int width, int height, int threads);
// The area drawn, in fragments (width, height): the strip's, or the image's for 0 tiles.
glm::ivec2 fragmentStripSize(int width, int height, int tiles);
// The tiles of the strip in which an adaptive render's rounds list the blocks that take them
// (fragment_layout.glsl): the image's strip, else one tile per thread, doubled while the strip of
// all `blocks` would be taller than kMaxAdaptiveStripHeight fragments and not wider than
// kMaxStripWidth (GL's framebuffer limit on llvmpipe; a 16384² image then needs 16384 rows).
constexpr int kMaxAdaptiveStripHeight = 4096;
constexpr int kMaxStripWidth = 16384;
int adaptiveStripTiles(int blocks, int stripTiles, int threads);
// llvmpipe's thread count: LP_NUM_THREADS, else the CPUs.
int rasterThreads();

class PathTracer {
public:
    explicit PathTracer(TracerOptions options = {});
    ~PathTracer();
    PathTracer(const PathTracer&) = delete;
    PathTracer& operator=(const PathTracer&) = delete;

    // Uploads the scene (geometry, materials, camera, sky, settings) relative to the camera's
    // position, which becomes origin(), and restarts accumulation.
    void setScene(const Scene& scene);
    // Objects moved (transforms, sphere centres; same meshes and materials): re-uploads only the
    // top level (the meshes' BVHs stay) and restarts accumulation.
    void updateTransforms(const Scene& scene);
    // Material values edited (same materials and textures): re-uploads the material records and
    // the light list, then as updateSettings.
    void updateMaterials(const Scene& scene);
    // Camera, sky values and render settings changed, with the scene's buffers as uploaded:
    // selects the variant for the scene's features, uploads the parameter block, reallocates the
    // image if its size changed, and restarts accumulation. A camera that left the region around
    // origin() (needsRebase, render/camera_relative.h) moves the origin to it: the top level alone
    // is uploaded again.
    void updateSettings(const Scene& scene);
    // Drops the accumulated samples; the next pass starts a new mean.
    void reset();
    // Continues a mean of `samplesPerPixel` samples made with the settings now uploaded (a resumed
    // render): `image` (top row first, as readImage gives it) becomes the accumulation, and the
    // next pass adds samples from there on. The image's size must be the scene's. An adaptive
    // render needs `adaptive`, as adaptiveState() gave it (its samples one count per block); its
    // samples per pixel are then the mean of those.
    void restoreAccumulation(const Image& image, std::uint64_t samplesPerPixel, std::uint64_t passes,
                             std::uint64_t nonFiniteSamples, const AdaptiveState* adaptive = nullptr);
    // render.adaptive: what restoreAccumulation needs beside the image to go on as this render would.
    AdaptiveState adaptiveState() const;
    // Traces rpp samples per pixel (the scene's render.rpp when rpp <= 0) and waits for them; an
    // adaptive render gives each block that takes the pass its passRounds(...) rounds of
    // passScale(...) times rpp (adaptive_sampling.h).
    void renderPass(int rpp = 0);
    // Time slicing for interactive use (the viewer): one pass may be traced as horizontal bands and
    // sample chunks. traceBand traces samples [spp + sampleOffset, + rpp) of rows [y, y + rows) and
    // adds to the counters; call it for every band of a chunk, chunk after chunk, then finishPass
    // with the pass's total rpp. Bands need the fragment entry (the compute entry traces all rows).
    // traceBand draws at most samplesPerDraw() samples per pixel at once (below). An adaptive
    // render plans its pass at the pass's first traceBand: only the blocks that take it get samples.
    void traceBand(int y, int rows, int sampleOffset, int rpp);
    void finishPass(int rpp);
    unsigned accumulationTexture() const { return accumTexture_; }   // RGBA32F, bottom row first
    const ShaderProgram& program() const { return *program_; }   // for uniforms of host extensions (after setScene)

    // Samples per pixel; with render.adaptive the mean over the pixels, rounded down.
    std::uint64_t samplesPerPixel() const { return samplesPerPixel_; }
    // render.adaptive is in effect (the scene asks for it, with sobol or independent, and no debug,
    // inspection or exercise define is set); then the samples each pixel holds.
    bool adaptive() const { return adaptive_; }
    std::vector<std::uint64_t> pixelSamples() const;   // top row first, as readImage
    std::uint64_t samplesAt(int x, int y) const;        // of image pixel (x, y), top-left origin
    // render.adaptive: each block's noise and cost as the next plan reads them (blockNoise), its
    // blocks in GL's rows (bottom first); blockSamples() the samples each holds.
    BlockNoise adaptiveNoise() const;
    // render.adaptive: the plans since the last reset that read the noise back to decide
    // (kAdaptiveGateRecheckGrowth spaces them while the gain is below kAdaptiveMinGain).
    std::uint64_t gainReads() const { return gainReads_; }
    const std::vector<std::uint64_t>& blockSamples() const { return blockSamples_; }
    const AdaptiveBlocks& adaptiveBlocks() const { return blocks_; }
    std::uint64_t passes() const { return passes_; }
    std::uint64_t nonFiniteSamples() const { return nonFinite_; }   // replaced by 0, counted
    std::uint64_t raysTraced() const { return rays_; }
    // llvmpipe ends all loops of a shader invocation after 65535 iterations in all (gallivm's loop
    // limiter), which would cut paths short without a word. So a draw traces at most this many
    // samples per pixel (a pass of more is several draws, the same samples in the same order), the
    // shader counts invocations that still ran out, and after such a draw later ones take half as
    // many. A variant whose loops have bounded trips (a flat search, few objects with small meshes)
    // takes as many samples as its loop iterations per sample (boundedLoopIterationsPerSample,
    // shader_variant.h) leave within half of kLoopIterationBudget, at most kBoundedSamplesPerDraw:
    // fewer draws, as each ends with a wait for the threads (bench/adaptive_sampling.md).
    // loopLimitedInvocations() > 0 means the image lacks light; raylab-render reports it.
    static constexpr int kSamplesPerDraw = 16;
    static constexpr int kBoundedSamplesPerDraw = 64;
    int samplesPerDraw() const { return std::min(samplesPerDraw_, variantSamplesPerDraw_); }
    std::uint64_t loopLimitedInvocations() const { return loopLimited_; }
    // With RAYLAB_COUNT_TRAVERSAL in extraDefines: BVH boxes and triangles tested (else 0).
    std::uint64_t boxTests() const { return boxTests_; }
    std::uint64_t triangleTests() const { return triangleTests_; }
    std::uint64_t pathsTraced() const;   // camera paths over all pixels
    int width() const { return width_; }
    int height() const { return height_; }

    Image readImage() const;
    // Compile time of the running variant (0 before setScene; a cached variant reports the time
    // it took when first compiled), and its name: entry point and scene features.
    double compileSeconds() const { return program_ ? program_->compileSeconds() : 0.0; }
    std::string variantName() const;
    // Programs compiled so far (one per feature set met; an edit that keeps the features compiles none).
    std::size_t compiledVariants() const { return variants_.size(); }
    const SceneFeatures& features() const { return features_; }
    const GpuScene& gpuScene() const { return gpuScene_; }
    // World position the GPU's coordinates are relative to (its (0, 0, 0)): add it to a position
    // read back from the GPU to get a world position.
    const glm::dvec3& origin() const { return origin_; }

private:
    void allocateImage(int width, int height);
    void drawBand(int y, int rows, int sampleOffset, int rpp);   // one draw of traceBand
    // finishPass for a pass whose blocks took min(their passRounds_, rounds) rounds of rpp samples
    // (renderPass traces them all; the viewer's slices one).
    void countPass(int rpp, int rounds);
    void uploadPlan(int round);   // render.adaptive: the plan image for the pass's round (its blocks with more rounds)
    void allocateAdaptiveImages();   // render.adaptive's plan and half images, once it is in effect
    void planPass();   // render.adaptive: each block's rounds of the pass (adaptive_sampling.h), round 0 uploaded

    static ShaderProgram compileVariant(const ShaderDefines& features, const void* self);

    TracerOptions options_;
    ShaderVariantCache variants_;
    const ShaderProgram* program_ = nullptr;   // the variant for the current scene
    SceneFeatures features_;
    GpuScene gpuScene_;
    glm::dvec3 origin_{0.0};
    unsigned accumTexture_ = 0;
    unsigned planTexture_ = 0;     // render.adaptive: R32UI, a pixel's samples so far or ADAPTIVE_SKIP
    unsigned halfTexture_ = 0;     // render.adaptive: RGBA32F, the half's running mean and rays per sample
    unsigned roundBlocksBuffer_ = 0;   // render.adaptive, fragment entry: the round's blocks in strip order
    int roundBlocks_ = 0;              // how many it lists
    int adaptiveTiles_ = 0;            // adaptiveStripTiles of the image; 0 for the compute entry
    bool adaptive_ = false;
    AdaptiveBlocks blocks_;
    std::vector<std::uint64_t> blockSamples_;   // render.adaptive: samples each block holds
    std::vector<std::uint8_t> passRounds_;      // the planned pass's rounds per block (passRounds; 0: sits it out)
    bool planned_ = false;                      // passRounds_ is the current pass's plan
    std::uint64_t gateClosedAt_ = 0;            // spp when the gain was last below kAdaptiveMinGain, else 0
    std::uint64_t gainReads_ = 0;               // plans that read the blocks' noise back
    unsigned framebuffer_ = 0;
    unsigned vertexArray_ = 0;
    unsigned counterBuffer_ = 0;
    glsl::TracerParams params_{};   // as uploaded to paramsBuffer_
    unsigned paramsBuffer_ = 0;     // uniform buffer at BINDING_TRACER_PARAMS_UBO
    int width_ = 0;
    int height_ = 0;
    int stripTiles_ = 0;   // fragmentStripTiles of the image, 0 when balanceTiles is off
    int defaultRpp_ = 1;
    std::uint64_t samplesPerPixel_ = 0;
    std::uint64_t passes_ = 0;
    std::uint64_t nonFinite_ = 0;
    std::uint64_t rays_ = 0;
    std::uint64_t loopLimited_ = 0;
    int samplesPerDraw_ = kBoundedSamplesPerDraw;   // halved after a draw the driver cut short
    int variantSamplesPerDraw_ = kSamplesPerDraw;   // the bound of a variant's loops, set per scene
    unsigned traversalBuffer_ = 0;   // only when counting traversal
    std::uint64_t boxTests_ = 0;
    std::uint64_t triangleTests_ = 0;
};

} // namespace raylab
