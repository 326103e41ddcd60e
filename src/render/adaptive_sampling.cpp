#include "render/adaptive_sampling.h"

#include "shaders/include/adaptive_sampling.glsl"
#include "shaders/include/fragment_layout.glsl"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raylab {

int AdaptiveBlocks::columns() const { return (width + glsl::FRAGMENT_BLOCK - 1) / glsl::FRAGMENT_BLOCK; }
int AdaptiveBlocks::rows() const { return (height + glsl::FRAGMENT_BLOCK - 1) / glsl::FRAGMENT_BLOCK; }
int AdaptiveBlocks::blockOf(int x, int y) const {
    return (y / glsl::FRAGMENT_BLOCK) * columns() + x / glsl::FRAGMENT_BLOCK;
}

BlockNoise blockNoise(const AdaptiveBlocks& blocks, std::span<const float> meanRgba, std::span<const float> moments) {
    const std::size_t pixels = std::size_t(blocks.width) * std::size_t(blocks.height);
    if (meanRgba.size() != 4 * pixels || moments.size() != 2 * pixels)
        throw std::invalid_argument("blockNoise: the images are not the blocks' size");
    const std::size_t n = std::size_t(blocks.count());
    std::vector<double> variance(n, 0.0), rays(n, 0.0);
    std::vector<int> count(n, 0);
    for (int y = 0; y < blocks.height; ++y)
        for (int x = 0; x < blocks.width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(blocks.width) + std::size_t(x);
            const double v = glsl::adaptiveValue(glm::vec3(meanRgba[4 * i], meanRgba[4 * i + 1], meanRgba[4 * i + 2]));
            const double var = double(moments[2 * i]) - v * v;
            const std::size_t b = std::size_t(blocks.blockOf(x, y));
            variance[b] += std::isfinite(var) ? std::max(var, 0.0) : 0.0;
            rays[b] += std::isfinite(moments[2 * i + 1]) ? double(moments[2 * i + 1]) : 0.0;
            ++count[b];
        }
    BlockNoise noise{std::vector<double>(n), std::vector<double>(n)};
    for (std::size_t b = 0; b < n; ++b) {
        const double pixelsIn = double(std::max(count[b], 1));
        noise.deviation[b] = std::sqrt(variance[b] / pixelsIn);
        noise.cost[b] = rays[b] / pixelsIn;
    }
    return noise;
}

std::vector<std::uint8_t> activeBlocks(std::span<const double> deviation, std::span<const double> cost,
                                       std::span<const std::uint64_t> samples) {
    if (deviation.size() != samples.size() || cost.size() != samples.size())
        throw std::invalid_argument("activeBlocks: one deviation and cost per block");
    std::vector<std::uint8_t> active(samples.size(), 1);
    if (samples.empty() || *std::min_element(samples.begin(), samples.end()) < kAdaptiveWarmupSamples) return active;
    double meanDeviation = 0.0;
    for (double s : deviation) meanDeviation += s;
    meanDeviation /= double(deviation.size());
    const double floor = kAdaptiveDeviationFloor * meanDeviation;
    std::vector<double> ratio(samples.size());
    double meanRatio = 0.0;
    for (std::size_t b = 0; b < samples.size(); ++b) {
        // A sample traces at least its camera ray.
        ratio[b] = std::max(deviation[b], floor) / (double(samples[b]) * std::sqrt(std::max(cost[b], 1.0)));
        meanRatio += ratio[b];
    }
    meanRatio /= double(samples.size());
    // Where the ratios are all alike (a furnace: no variance anywhere) every block takes the pass,
    // the mean's rounding aside.
    const double threshold = meanRatio * (1.0 - 1e-9);
    for (std::size_t b = 0; b < samples.size(); ++b) active[b] = ratio[b] >= threshold ? 1 : 0;
    if (std::find(active.begin(), active.end(), 1) == active.end())   // rounding: the largest ratio takes it
        active[std::size_t(std::max_element(ratio.begin(), ratio.end()) - ratio.begin())] = 1;
    return active;
}

} // namespace raylab
