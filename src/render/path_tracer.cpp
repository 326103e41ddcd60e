#include "render/path_tracer.h"

#include "render/camera_relative.h"
#include "render/light_list.h"
#include "shaders/include/adaptive_sampling.glsl"
#include "shaders/include/bindings.glsl"
#include "shaders/include/camera.glsl"
#include "shaders/include/fragment_layout.glsl"
#include "shaders/include/sky.glsl"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <thread>
#include <vector>

namespace raylab {
namespace {

int skyType(Sky::Type t) {
    if (t == Sky::Type::Map) return glsl::SKY_MAP;
    return t == Sky::Type::Constant ? glsl::SKY_CONSTANT : glsl::SKY_GRADIENT;
}

} // namespace

ShaderProgram PathTracer::compileVariant(const ShaderDefines& features, const void* self) {
    const TracerOptions& o = static_cast<const PathTracer*>(self)->options_;
    ShaderDefines defines = o.extraDefines;
    defines.insert(defines.end(), features.begin(), features.end());
    if (o.entry == TracerEntry::Fragment)
        return ShaderProgram::graphics("entry/fullscreen.vert", "entry/trace.frag", defines);
    defines.emplace_back(tracerDefine("LOCAL_SIZE_X"), std::to_string(o.localSizeX));
    defines.emplace_back(tracerDefine("LOCAL_SIZE_Y"), std::to_string(o.localSizeY));
    return ShaderProgram::compute("entry/trace.comp", defines);
}

PathTracer::PathTracer(TracerOptions options) : options_(options) {
    for (const auto& [name, value] : options_.extraDefines) {
        if (name != tracerDefine("RAYLAB_COUNT_TRAVERSAL")) continue;
        glCreateBuffers(1, &traversalBuffer_);
        const GLuint zeros[2] = {0, 0};
        glNamedBufferStorage(traversalBuffer_, sizeof(zeros), zeros, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    }
    glCreateFramebuffers(1, &framebuffer_);
    glCreateVertexArrays(1, &vertexArray_);
    glCreateBuffers(1, &counterBuffer_);
    const GLuint zeros[3] = {0, 0, 0};
    glNamedBufferStorage(counterBuffer_, sizeof(zeros), zeros,
                         GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    glCreateBuffers(1, &paramsBuffer_);
    glNamedBufferStorage(paramsBuffer_, sizeof(params_), &params_, GL_DYNAMIC_STORAGE_BIT);
}

PathTracer::~PathTracer() {
    glDeleteTextures(1, &accumTexture_);
    glDeleteTextures(1, &planTexture_);
    glDeleteTextures(1, &halfTexture_);
    glDeleteBuffers(1, &roundBlocksBuffer_);
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteBuffers(1, &counterBuffer_);
    glDeleteBuffers(1, &paramsBuffer_);
    if (traversalBuffer_) glDeleteBuffers(1, &traversalBuffer_);
}

std::string PathTracer::variantName() const {
    std::string entry = options_.entry == TracerEntry::Fragment
                            ? "fragment"
                            : "compute " + std::to_string(options_.localSizeX) + "x" + std::to_string(options_.localSizeY);
    return entry + " [" + (options_.specialise ? featureName(features_) : "all features") + "]";
}

int fragmentStripTiles(int width, int height, int threads) {
    const auto tiles = [](int n) { return (n + glsl::RASTER_TILE - 1) / glsl::RASTER_TILE; };
    return threads < 2 || tiles(width) * tiles(height) >= 4 * threads ? 0 : threads;
}

glm::ivec2 fragmentStripSize(int width, int height, int tiles) {
    if (tiles == 0) return {width, height};
    const auto blocks = [](int n) { return (n + glsl::FRAGMENT_BLOCK - 1) / glsl::FRAGMENT_BLOCK; };
    return glsl::fragmentStripExtent(blocks(width) * blocks(height), tiles);
}

int adaptiveStripTiles(int blocks, int stripTiles, int threads) {
    int tiles = stripTiles > 0 ? stripTiles : std::max(1, threads);
    while (glsl::fragmentStripExtent(blocks, tiles).y > kMaxAdaptiveStripHeight &&
           2 * tiles * glsl::RASTER_TILE <= kMaxStripWidth)
        tiles *= 2;
    return tiles;
}

int rasterThreads() {
    if (const char* env = std::getenv("LP_NUM_THREADS")) {
        char* end = nullptr;
        const long n = std::strtol(env, &end, 10);
        if (end != env && *end == '\0' && n >= 0 && n <= 1024) return int(n);
    }
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

void PathTracer::allocateImage(int width, int height) {
    if (width == width_ && height == height_ && accumTexture_) return;
    glDeleteTextures(1, &accumTexture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &accumTexture_);
    glTextureStorage2D(accumTexture_, 1, GL_RGBA32F, width, height);
    // render.adaptive's images follow the size; allocateAdaptiveImages makes them when needed.
    glDeleteTextures(1, &planTexture_);
    glDeleteTextures(1, &halfTexture_);
    glDeleteBuffers(1, &roundBlocksBuffer_);
    planTexture_ = halfTexture_ = roundBlocksBuffer_ = 0;
    blocks_ = AdaptiveBlocks{width, height};
    const bool fragment = options_.entry == TracerEntry::Fragment;
    stripTiles_ = fragment && options_.balanceTiles ? fragmentStripTiles(width, height, rasterThreads()) : 0;
    adaptiveTiles_ = fragment && options_.balanceTiles ? adaptiveStripTiles(blocks_.count(), stripTiles_, rasterThreads()) : 0;
    // The fragment entry draws into a framebuffer with no attachments, sized here to hold the
    // image, its strip, and an adaptive round's strip of every block.
    const glm::ivec2 strip = fragmentStripSize(width, height, stripTiles_);
    const glm::ivec2 rounds = adaptiveTiles_ > 0 ? glsl::fragmentStripExtent(blocks_.count(), adaptiveTiles_) : glm::ivec2(0);
    glNamedFramebufferParameteri(framebuffer_, GL_FRAMEBUFFER_DEFAULT_WIDTH, std::max({width, strip.x, rounds.x}));
    glNamedFramebufferParameteri(framebuffer_, GL_FRAMEBUFFER_DEFAULT_HEIGHT, std::max({height, strip.y, rounds.y}));
    width_ = width;
    height_ = height;
}

void PathTracer::allocateAdaptiveImages() {
    if (!adaptive_ || planTexture_) return;
    glCreateTextures(GL_TEXTURE_2D, 1, &planTexture_);
    glTextureStorage2D(planTexture_, 1, GL_R32UI, width_, height_);
    glCreateTextures(GL_TEXTURE_2D, 1, &halfTexture_);
    glTextureStorage2D(halfTexture_, 1, GL_RGBA32F, width_, height_);
    glCreateBuffers(1, &roundBlocksBuffer_);
    glNamedBufferStorage(roundBlocksBuffer_, GLsizeiptr(std::size_t(blocks_.count()) * sizeof(GLuint)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
}

namespace {

// RGBA rows in the other order: GL keeps the bottom row first, images the top row.
std::vector<float> flippedRows(const std::vector<float>& rgba, int width, int height) {
    const std::size_t row = std::size_t(width) * 4;
    std::vector<float> out(rgba.size());
    for (int y = 0; y < height; ++y)
        std::copy_n(rgba.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row), row,
                    out.begin() + std::ptrdiff_t(std::size_t(y) * row));
    return out;
}

} // namespace

void PathTracer::setScene(const Scene& scene) {
    origin_ = options_.cameraRelative ? glm::dvec3(scene.camera.position) : glm::dvec3(0.0);
    gpuScene_.upload(scene, origin_);
    updateSettings(scene);
}

void PathTracer::updateMaterials(const Scene& scene) {
    gpuScene_.updateMaterials(scene, origin_);
    updateSettings(scene);
}

void PathTracer::updateSettings(const Scene& scene) {
    const RenderSettings& r = scene.render;
    allocateImage(r.width, r.height);
    defaultRpp_ = r.rpp;

    // The feature set may change with any edit (an aperture above 0, glass, a sky that emits):
    // the variant is looked up again, and compiled only when that set was never met.
    features_ = options_.specialise ? sceneFeatures(scene) : allFeatures();
    // The debug views, the inspector and the exercises trace every pixel alike (their own loops).
    if (!options_.extraDefines.empty()) features_.adaptive = false;
    adaptive_ = features_.adaptive;
    allocateAdaptiveImages();
    program_ = &variants_.get(featureDefines(features_), &PathTracer::compileVariant, this);
    if (features_.linearTopLevel &&
        (features_.objectCount != gpuScene_.instanceCount() || features_.sphereCount != gpuScene_.sphereCount()))
        throw std::logic_error("path tracer: the variant's object counts are not the scene's");
    // The variant's search, not the scene's key: the unspecialised tracer always walks the BVH.
    const std::uint64_t iterations = boundedLoopIterationsPerSample(scene, features_, !options_.extraDefines.empty());
    variantSamplesPerDraw_ =
        iterations == 0 ? kSamplesPerDraw
                        : int(std::clamp<std::uint64_t>(kLoopIterationBudget / 2 / iterations, 1, kBoundedSamplesPerDraw));

    if (options_.cameraRelative && needsRebase(scene.camera, origin_)) {
        origin_ = glm::dvec3(scene.camera.position);
        gpuScene_.updateTransforms(scene, origin_);
    }
    const Camera& c = scene.camera;
    const glm::vec3 eye = relativePoint(c.position, origin_);
    const glm::vec3 lookAt = relativePoint(c.lookAt, origin_);
    const auto cam = glsl::cameraBasis(eye, lookAt, c.up, c.fovY, float(r.width) / float(r.height));
    const Sky& sky = scene.sky;
    const bool skyIsLight = skyMayEmit(sky) && (sky.type != Sky::Type::Map || gpuScene_.skyMapMax() > 0.0f);
    // The variant leaves out the light kinds the scene lacks (sceneFeatures): the scene must agree.
    if (options_.specialise && r.nee &&
        ((gpuScene_.lightCount() > 0 && !features_.sphereLights) || (skyIsLight && !features_.skyLight)))
        throw std::logic_error("path tracer: the variant lacks a light the scene has");
    params_ = glsl::TracerParams{
        .sampleStart = 0,   // sampleStart and rpp: set per band by traceBand
        .rpp = 0,
        .imageSize = glm::ivec2(r.width, r.height),
        .seed = r.seed,
        .maxBounces = r.maxBounces,
        .rrDepth = r.rrDepth,
        .sphereCount = gpuScene_.sphereCount(),
        .camOrigin = cam.origin,
        .camTanHalfFovY = cam.tanHalfFovY,
        .camRight = cam.right,
        .camAspect = cam.aspect,
        .camUp = cam.up,
        .camLensRadius = c.aperture,
        .camForward = cam.forward,
        // focus_distance 0 means "at look_at": its distance along the view axis.
        .camFocusDistance = c.focusDistance > 0.0f ? c.focusDistance : glm::dot(lookAt - eye, cam.forward),
        .skyColor = sky.color * sky.strength,
        // Ray-cone spread of one pixel (Ray Tracing Gems ch. 20, eq. 30).
        .camPixelSpread = std::atan(2.0f * cam.tanHalfFovY / float(r.height)),
        .skyTop = sky.top * sky.strength,
        .skyType = skyType(sky.type),
        .skyBottom = sky.bottom * sky.strength,
        .skyMapScale = sky.strength,
        .skyRotation = glm::radians(sky.rotation),
        .envMeanWeight = gpuScene_.skyMapMeanWeight(),
        .lightCount = gpuScene_.lightCount(),
        .triangleLightCount = gpuScene_.triangleLightCount(),
        .nee = r.nee,
        .mis = r.mis,
        .skyIsLight = r.nee && skyIsLight,
        .sampleCount = std::uint32_t(std::max(r.spp, 1)),
        .aoDistance = scene.ao.distance,
        .aoRays = scene.ao.rays,
        .fragmentStripTiles = 0,   // set per draw by drawBand
        .fragmentStripBlocks = 0,   // set per draw by drawBand
    };
    glNamedBufferSubData(paramsBuffer_, 0, sizeof(params_), &params_);
    reset();
}

void PathTracer::updateTransforms(const Scene& scene) {
    gpuScene_.updateTransforms(scene, origin_);
    // The variant follows the transforms (whether every mesh shares one): looked up again, and
    // the image reset.
    updateSettings(scene);
}

void PathTracer::reset() {
    const float zero[4] = {0, 0, 0, 0};
    if (accumTexture_) glClearTexImage(accumTexture_, 0, GL_RGBA, GL_FLOAT, zero);
    if (halfTexture_) glClearTexImage(halfTexture_, 0, GL_RGBA, GL_FLOAT, zero);
    blockSamples_.assign(std::size_t(blocks_.count()), 0);
    passRounds_.clear();
    planned_ = false;
    gateClosedAt_ = 0;
    gainReads_ = 0;
    samplesPerPixel_ = 0;
    passes_ = 0;
    nonFinite_ = 0;
    rays_ = 0;
    loopLimited_ = 0;
    boxTests_ = 0;
    triangleTests_ = 0;
}

void PathTracer::restoreAccumulation(const Image& image, std::uint64_t samplesPerPixel, std::uint64_t passes,
                                     std::uint64_t nonFiniteSamples, const AdaptiveState* adaptive) {
    if (image.width != width_ || image.height != height_)
        throw std::invalid_argument("PathTracer::restoreAccumulation: the image is " + std::to_string(image.width) +
                                    "x" + std::to_string(image.height) + ", the scene renders " +
                                    std::to_string(width_) + "x" + std::to_string(height_));
    std::vector<std::uint64_t> counts;   // checked before anything changes
    if (adaptive_) {
        if (!adaptive)
            throw std::invalid_argument("PathTracer::restoreAccumulation: an adaptive render (render.adaptive) goes "
                                        "on only with its per-pixel samples and half image");
        if (adaptive->half.size() != image.rgba.size())
            throw std::invalid_argument("PathTracer::restoreAccumulation: the half image is not of the image's size");
        try {
            counts = blockSamplesOf(blocks_, adaptive->samples);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(std::string("PathTracer::restoreAccumulation: ") + e.what());
        }
    }
    reset();
    glTextureSubImage2D(accumTexture_, 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT,
                        flippedRows(image.rgba, width_, height_).data());
    samplesPerPixel_ = samplesPerPixel;
    passes_ = passes;
    nonFinite_ = nonFiniteSamples;
    if (!adaptive_) return;
    glTextureSubImage2D(halfTexture_, 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT,
                        flippedRows(adaptive->half, width_, height_).data());
    blockSamples_ = std::move(counts);
    gateClosedAt_ = adaptive->gateClosedAt;
    samplesPerPixel_ = pathsTraced() / (std::uint64_t(width_) * std::uint64_t(height_));
}

AdaptiveState PathTracer::adaptiveState() const {
    if (!adaptive_) throw std::logic_error("PathTracer::adaptiveState: not an adaptive render");
    AdaptiveState s;
    for (std::uint64_t n : pixelSamples())
        s.samples.push_back(std::uint32_t(std::min<std::uint64_t>(n, glsl::ADAPTIVE_SKIP - 1u)));
    std::vector<float> raw(4 * s.samples.size());
    glGetTextureImage(halfTexture_, 0, GL_RGBA, GL_FLOAT, GLsizei(raw.size() * sizeof(float)), raw.data());
    s.half = flippedRows(raw, width_, height_);
    s.gateClosedAt = gateClosedAt_;
    return s;
}

void PathTracer::renderPass(int rpp) {
    if (rpp <= 0) rpp = defaultRpp_;
    if (adaptive_) {
        if (!planned_) planPass();
        rpp *= int(passScale(blocks_, passRounds_));
        const int rounds = int(*std::max_element(passRounds_.begin(), passRounds_.end()));
        for (int k = 0; k < rounds; ++k) {
            if (k > 0) uploadPlan(k);
            traceBand(0, height_, k * rpp, rpp);
        }
        countPass(rpp, rounds);
        return;
    }
    traceBand(0, height_, 0, rpp);
    finishPass(rpp);
}

void PathTracer::traceBand(int y, int rows, int sampleOffset, int rpp) {
    if (!accumTexture_) throw std::logic_error("PathTracer::renderPass before setScene");
    if (adaptive_ && !planned_) planPass();
    // As few draws as samplesPerDraw() allows (it may fall after a draw), of nearly equal size.
    for (int done = 0; done < rpp;) {
        const int left = rpp - done;
        const int draws = (left + samplesPerDraw() - 1) / samplesPerDraw();
        const int n = (left + draws - 1) / draws;
        drawBand(y, rows, sampleOffset + done, n);
        done += n;
    }
}

void PathTracer::drawBand(int y, int rows, int sampleOffset, int rpp) {
    // Adaptive: each pixel's count is in the plan, and sampleStart is the draw's offset in the pass.
    params_.sampleStart = unsigned((adaptive_ ? 0 : samplesPerPixel_) + std::uint64_t(sampleOffset));
    params_.rpp = rpp;
    glNamedBufferSubData(paramsBuffer_, offsetof(glsl::TracerParams, sampleStart),
                         sizeof(params_.sampleStart) + sizeof(params_.rpp), &params_.sampleStart);
    // A band (the viewer's, the inspector's row) is drawn as rows of the image, the whole image
    // of a small one as its strip.
    const bool band = y > 0 || rows < height_;
    // A whole adaptive draw's strip lists only the blocks that take its round (uploadPlan).
    const bool listed = adaptive_ && !band && adaptiveTiles_ > 0;
    const int tiles = listed ? adaptiveTiles_ : band ? 0 : stripTiles_;
    const int stripBlocks = listed ? roundBlocks_ : 0;
    if (params_.fragmentStripTiles != tiles || params_.fragmentStripBlocks != stripBlocks) {
        params_.fragmentStripTiles = tiles;
        params_.fragmentStripBlocks = stripBlocks;
        glNamedBufferSubData(paramsBuffer_, offsetof(glsl::TracerParams, fragmentStripTiles),
                             sizeof(params_.fragmentStripTiles) + sizeof(params_.fragmentStripBlocks),
                             &params_.fragmentStripTiles);
    }

    const GLuint zeros[3] = {0, 0, 0};
    glNamedBufferSubData(counterBuffer_, 0, sizeof(zeros), zeros);
    glBindImageTexture(BINDING_ACCUM_IMAGE, accumTexture_, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    if (adaptive_) {
        glBindImageTexture(BINDING_SAMPLE_PLAN_IMAGE, planTexture_, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
        glBindImageTexture(BINDING_ADAPTIVE_HALF_IMAGE, halfTexture_, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_ADAPTIVE_BLOCKS, roundBlocksBuffer_);
    }
    gpuScene_.bind();
    glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_TRACER_PARAMS_UBO, paramsBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_COUNTERS, counterBuffer_);
    if (traversalBuffer_) {
        glNamedBufferSubData(traversalBuffer_, 0, 2 * sizeof(GLuint), zeros);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_TRAVERSAL_COUNTERS, traversalBuffer_);
    }
    glUseProgram(program_->id());
    if (options_.entry == TracerEntry::Fragment) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        const glm::ivec2 viewport = listed ? glsl::fragmentStripExtent(stripBlocks, tiles)
                                           : fragmentStripSize(width_, height_, tiles);
        glViewport(0, 0, viewport.x, viewport.y);
        if (band) {   // the full-screen triangle, cut to the band's rows
            glEnable(GL_SCISSOR_TEST);
            glScissor(0, y, width_, rows);
        }
        glBindVertexArray(vertexArray_);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        if (band) glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    } else {
        const auto groups = [](int n, int size) { return GLuint((n + size - 1) / size); };
        glDispatchCompute(groups(width_, options_.localSizeX), groups(height_, options_.localSizeY), 1);
    }
    // The next pass reads what this one stored; the counters are read back below.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint counters[3] = {0, 0, 0};
    glGetNamedBufferSubData(counterBuffer_, 0, sizeof(counters), counters);   // waits for the pass
    nonFinite_ += counters[0];
    rays_ += counters[1];
    loopLimited_ += counters[2];
    if (counters[2] > 0) samplesPerDraw_ = std::max(1, samplesPerDraw() / 2);
    if (traversalBuffer_) {
        glGetNamedBufferSubData(traversalBuffer_, 0, 2 * sizeof(GLuint), counters);
        boxTests_ += counters[0];
        triangleTests_ += counters[1];
    }
}

void PathTracer::finishPass(int rpp) { countPass(rpp, 1); }

void PathTracer::countPass(int rpp, int rounds) {
    ++passes_;
    if (!adaptive_) {
        samplesPerPixel_ += std::uint64_t(rpp);
        return;
    }
    if (!planned_) return;   // no band of this pass was traced
    for (std::size_t b = 0; b < blockSamples_.size(); ++b)
        blockSamples_[b] += std::uint64_t(rpp) * std::uint64_t(std::min<int>(passRounds_[b], rounds));
    samplesPerPixel_ = pathsTraced() / (std::uint64_t(width_) * std::uint64_t(height_));
    planned_ = false;
}

void PathTracer::planPass() {
    if (*std::min_element(blockSamples_.begin(), blockSamples_.end()) < kAdaptiveWarmupSamples ||
        (gateClosedAt_ > 0 && double(samplesPerPixel_) < kAdaptiveGateRecheckGrowth * double(gateClosedAt_))) {
        passRounds_.assign(blockSamples_.size(), 1);
    } else {
        const BlockNoise noise = adaptiveNoise();
        ++gainReads_;
        if (adaptiveGain(noise.deviation, noise.cost) < kAdaptiveMinGain) {
            passRounds_.assign(blockSamples_.size(), 1);
            gateClosedAt_ = std::max<std::uint64_t>(samplesPerPixel_, 1);
        } else {
            passRounds_ = passRounds(blocks_, noise.deviation, noise.cost, blockSamples_);
            gateClosedAt_ = 0;
        }
    }
    uploadPlan(0);
    planned_ = true;
}

void PathTracer::uploadPlan(int round) {
    const std::size_t pixels = std::size_t(width_) * std::size_t(height_);
    std::vector<GLuint> plan(pixels);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const std::size_t b = std::size_t(blocks_.blockOf(x, y));
            plan[std::size_t(y) * std::size_t(width_) + std::size_t(x)] =
                passRounds_[b] > round ? GLuint(std::min<std::uint64_t>(blockSamples_[b], glsl::ADAPTIVE_SKIP - 1u))
                                       : glsl::ADAPTIVE_SKIP;
        }
    glTextureSubImage2D(planTexture_, 0, 0, 0, width_, height_, GL_RED_INTEGER, GL_UNSIGNED_INT, plan.data());
    std::vector<GLuint> taking;
    for (std::size_t b = 0; b < passRounds_.size(); ++b)
        if (passRounds_[b] > round) taking.push_back(GLuint(b));
    roundBlocks_ = int(taking.size());
    glNamedBufferSubData(roundBlocksBuffer_, 0, GLsizeiptr(taking.size() * sizeof(GLuint)), taking.data());
}

BlockNoise PathTracer::adaptiveNoise() const {
    if (!adaptive_) throw std::logic_error("PathTracer::adaptiveNoise: not an adaptive render");
    // Both images as GL keeps them, bottom row first: the blocks are counted in those rows too.
    const std::size_t pixels = std::size_t(width_) * std::size_t(height_);
    std::vector<float> mean(4 * pixels), half(4 * pixels);
    glGetTextureImage(accumTexture_, 0, GL_RGBA, GL_FLOAT, GLsizei(mean.size() * sizeof(float)), mean.data());
    glGetTextureImage(halfTexture_, 0, GL_RGBA, GL_FLOAT, GLsizei(half.size() * sizeof(float)), half.data());
    return blockNoise(blocks_, mean, half, blockSamples_);
}

std::uint64_t PathTracer::pathsTraced() const {
    if (!adaptive_) return samplesPerPixel_ * std::uint64_t(width_) * std::uint64_t(height_);
    return pathsIn(blocks_, blockSamples_);
}

std::uint64_t PathTracer::samplesAt(int x, int y) const {
    return adaptive_ ? blockSamples_[std::size_t(blocks_.blockOf(x, height_ - 1 - y))] : samplesPerPixel_;
}

std::vector<std::uint64_t> PathTracer::pixelSamples() const {
    std::vector<std::uint64_t> samples;
    samples.reserve(std::size_t(width_) * std::size_t(height_));
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) samples.push_back(samplesAt(x, y));
    return samples;
}

Image PathTracer::readImage() const {
    Image image(width_, height_);
    std::vector<float> raw(image.rgba.size());
    glGetTextureImage(accumTexture_, 0, GL_RGBA, GL_FLOAT, GLsizei(raw.size() * sizeof(float)),
                      raw.data());
    image.rgba = flippedRows(raw, width_, height_);
    return image;
}

} // namespace raylab
