#pragma once
// Per-pixel adaptive sampling (render.adaptive; shaders/include/adaptive_sampling.glsl): which
// blocks of FRAGMENT_BLOCK × FRAGMENT_BLOCK pixels take the next pass. A block shares one sample
// count, so llvmpipe's 8-lane batches (half a block) never wait on a neighbour with more samples.
// No GL here: PathTracer reads the images back and uploads the plan.
#include <cstdint>
#include <span>
#include <vector>

namespace raylab {

// Every block takes every pass until each holds this many samples, so each pixel's variance is
// estimated from at least this many before the first decision.
constexpr std::uint64_t kAdaptiveWarmupSamples = 16;
// A block's deviation counts as at least this share of the mean block's, so that a block whose
// first samples happened to agree (a rare bright path not met yet) still gets samples, at a lower rate.
constexpr double kAdaptiveDeviationFloor = 0.05;

// Blocks of an image, FRAGMENT_BLOCK pixels square (the last row and column may be cut off).
struct AdaptiveBlocks {
    int width = 0;    // image, pixels
    int height = 0;
    int columns() const;
    int rows() const;
    int count() const { return columns() * rows(); }
    int blockOf(int x, int y) const;   // the block of pixel (x, y)
};

// Per block: its noise per sample, the root of its pixels' mean sample variance E[v²] − E[v]² with v
// the mean of R, G and B (adaptiveValue), and its cost, its pixels' mean rays per sample; from the
// running mean (RGBA per pixel) and the tracer's running moments (per pixel: the second moment of
// v, then rays per sample), both in the same row order.
struct BlockNoise {
    std::vector<double> deviation;
    std::vector<double> cost;
};
BlockNoise blockNoise(const AdaptiveBlocks& blocks, std::span<const float> meanRgba, std::span<const float> moments);

// Which blocks take the next pass (1) and which sit it out (0), from each block's deviation s, its
// cost c (rays per sample, at least 1) and the samples n it holds. While a block holds fewer than
// kAdaptiveWarmupSamples, all take it. Then a block takes it when s/(n·√c) (s floored at
// kAdaptiveDeviationFloor of the mean s) is at least the mean of that over the blocks: the image's
// MSE is the mean of s²/n, so per unit of time a sample lowers it most where s²/(n²·c) is largest,
// and at the fixed point n ∝ s/√c, the spreading that minimises the MSE for the time spent
// (minimise Σ s²/n with Σ n·c fixed). At least one block always takes the pass.
std::vector<std::uint8_t> activeBlocks(std::span<const double> deviation, std::span<const double> cost,
                                       std::span<const std::uint64_t> samples);

} // namespace raylab
