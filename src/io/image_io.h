#pragma once
// Image files through OpenImageIO. EXR is written linear (float) with render metadata; PNG is
// exposed, tone mapped and sRGB-encoded to 8 bits. Every write is atomic: a temporary file in the
// target directory, then a rename, so an interrupted program never leaves a truncated image.
#include "render/adaptive_sampling.h"
#include "render/image.h"
#include "scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

class ImageIoError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// What an EXR records about its render (attributes raylab:*), enough to resume it (render/resume.h).
struct RenderMetadata {
    std::uint64_t spp = 0;                 // samples per pixel in the image
    double renderSeconds = 0.0;
    std::uint32_t seed = 0;
    std::string sceneFile;
    std::uint64_t nonFiniteSamples = 0;
    std::string sampler = "independent";   // render.sampler, as the scene writes it
    // The estimator's stages (scene/estimator_stages.h) as attributes raylab:<name>; a stage
    // missing from an older file is left out.
    std::vector<std::pair<std::string, std::string>> stages;
    std::uint64_t targetSpp = 0;           // render.spp of the run (stratified lays its strata out for it)
    int rpp = 0;                           // samples per pass
    std::uint64_t passes = 0;
    std::string tracer;                    // entry point: fragment or compute
    std::string settingsHash;              // of the scene and settings but spp and time (settingsHash())
    std::string version = RAYLAB_VERSION;  // of the program that wrote it
};

struct DisplayTransform {
    float exposure = 0.0f;   // EV stops
    ToneMap toneMap = ToneMap::AcesFit;
};

// The shader's TONE_MAP_* (shaders/include/tone_map.glsl) for a scene's tone map: the one mapping
// the CPU path here and the GPU display pass (render/display_pass.h) share.
int toneMapOp(ToneMap toneMap);

enum class ImageFormat { Exr, Png };

// From the extension (.exr, .png; case-insensitive); throws ImageIoError naming the path otherwise.
ImageFormat imageFormatFor(const std::filesystem::path& path);

// Fails early (before a long render) if the file cannot be created in its directory.
void checkWritable(const std::filesystem::path& path);

// An EXR of an adaptive render also takes its `adaptive` state, so that --resume can go on with it:
// the channels adaptive.samples (uint), adaptive.half.R, .G, .B and adaptive.rays (float) after
// R, G, B, A, and the attribute raylab:adaptive_gate_closed_at. A PNG leaves it out.
void writeImage(const std::filesystem::path& path, const Image& image, const RenderMetadata& meta,
                const DisplayTransform& display, const AdaptiveState* adaptive = nullptr);

// The adaptive state of an EXR that writeImage gave one; nullopt when it has none of its channels.
// Throws ImageIoError naming the file and what is missing when it has only some.
std::optional<AdaptiveState> readAdaptiveState(const std::filesystem::path& path);

// Reads any format OpenImageIO knows as linear float RGBA (for tests and tools).
Image readImage(const std::filesystem::path& path);

// The raylab:* attributes of an EXR that raylab-render wrote. Throws ImageIoError naming the file
// when it cannot be read or is not such an EXR (an attribute missing or of the wrong type, by name).
RenderMetadata readRenderMetadata(const std::filesystem::path& path);

// The 8-bit display value of a linear channel (exposure, tone curve, sRGB).
std::uint8_t displayByte(float linear, const DisplayTransform& display);

} // namespace raylab
