#pragma once
// References for error measurement: an analytic image, or the mean of independent long renders
// (one per seed) cached on disk as EXR with the per-pixel variance of that mean and a JSON sidecar
// recording how it was made. A cache whose sidecar key differs (other scene text, size, spp,
// renderer version) is rendered again.
#include "render/image.h"
#include "render/path_tracer.h"

#include <glm/glm.hpp>

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace raylab {

struct Reference {
    Image mean;
    Image variance;          // per-pixel variance of `mean` as an estimate; zero when analytic
    std::string description; // "analytic [0.5, 0.5, 0.5]" or "mean of 8 renders × 1024 spp"
    std::string command;     // how it was made
    double seconds = 0.0;    // time it took to make (0 when loaded from the cache)
    bool fromCache = false;
};

Reference analyticReference(int width, int height, glm::vec3 value);

// Batch k of raylab's reference of `scene`: spp samples with seed 1000 + k, at least 16 a pass.
// Stops early (an incomplete image) once *stop is set.
Image renderReferenceBatch(PathTracer& tracer, const Scene& scene, int k, int spp,
                           const std::atomic<bool>* stop = nullptr);

// The mean of renderBatch(0 … batches−1) (independent renders, batches ≥ 1) and the variance of
// that mean per pixel (0 for one batch), timed.
Reference batchReference(int batches, const std::function<Image(int)>& renderBatch, const std::string& description,
                         const std::string& command);
// batchReference, cached on disk. renderBatch(k) renders independent batch k (k = 0 … batches−1, a different seed each).
Reference cachedReference(const std::filesystem::path& cacheBase, const std::string& key, int batches,
                          const std::function<Image(int)>& renderBatch, const std::string& description,
                          const std::string& command);

// FNV-1a 64-bit of a file's bytes, as hex (stable across runs and machines): part of cache keys.
std::string fileHash(const std::filesystem::path& file);
std::string textHash(std::string_view text);

} // namespace raylab
