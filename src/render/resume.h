#pragma once
// Resuming a render from its EXR (raylab-render --resume): the image is the float32 running mean
// and its raylab:* attributes say how it was made, so the passes can go on where they stopped.
// The continuation adds the same samples in the same passes as one uninterrupted run, so the result
// is that run's image bit for bit when the EXR stopped at a pass boundary of it: always so for a
// render stopped by Ctrl-C or its time budget; for a target spp, when no pass was cut short to meet
// it (a multiple of rpp with even sampling). An adaptive render's EXR carries its per-pixel samples,
// half image and gain gate (AdaptiveState), so it goes on as it would have.
#include "io/image_io.h"
#include "render/image.h"
#include "scene/scene.h"

#include <filesystem>
#include <optional>
#include <string>

namespace raylab {

// A 64-bit FNV-1a hash (hex) of everything that decides the samples but the target spp and the
// time budget: the scene written back through the parameter table (scene/scene_writer.h), with the
// meshes' and textures' loaded data. The sky map is compared by its path.
std::string settingsHash(const Scene& scene);

struct ResumePoint {
    Image image;                            // the running mean, top row first
    RenderMetadata meta;                    // as recorded
    std::optional<AdaptiveState> adaptive;  // an adaptive render's state (readAdaptiveState)
};

// Reads `exr` and checks it against `scene` (as loaded with the command line's overrides) and the
// tracer entry: throws ImageIoError "FILE: error: ..." naming the first attribute that differs, or
// the file's problem when it is not a raylab EXR, or a target below the samples already there.
ResumePoint readResumePoint(const std::filesystem::path& exr, const Scene& scene, const std::string& tracer);

} // namespace raylab
