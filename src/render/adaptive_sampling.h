#pragma once
// Per-pixel adaptive sampling (render.adaptive; shaders/include/adaptive_sampling.glsl): which
// blocks of FRAGMENT_BLOCK × FRAGMENT_BLOCK pixels take the next pass. A block shares one sample
// count, so llvmpipe's 8-lane batches (half a block) never wait on a neighbour with more samples.
// No GL here: PathTracer reads the images back and uploads the plan.
#include <cstdint>
#include <span>
#include <vector>

namespace raylab {

// Every block takes every pass until each holds this many samples, so that each pixel's error is
// estimated from at least this many (its half and the other half, ADAPTIVE_HALF_RUN each) before
// the first decision.
constexpr std::uint64_t kAdaptiveWarmupSamples = 16;
// A block's deviation counts as at least this share of the mean block's, so that a block whose
// first samples happened to agree (a rare bright path not met yet) still gets samples, at a lower rate.
constexpr double kAdaptiveDeviationFloor = 0.05;

// What an adaptive render holds beside its running mean, so that it can go on later (raylab-render
// --resume; PathTracer::adaptiveState): per pixel the samples it holds and its half image (the half's
// running mean, then rays per sample: blockNoise's `halfRgba`), both top row first, and the spp at
// which the gain gate last closed (0 while open; kAdaptiveGateRecheckGrowth).
struct AdaptiveState {
    std::vector<std::uint32_t> samples;
    std::vector<float> half;
    std::uint64_t gateClosedAt = 0;
};

// Blocks of an image, FRAGMENT_BLOCK pixels square (the last row and column may be cut off).
struct AdaptiveBlocks {
    int width = 0;    // image, pixels
    int height = 0;
    int columns() const;
    int rows() const;
    int count() const { return columns() * rows(); }
    int blockOf(int x, int y) const;   // the block of pixel (x, y)
    int pixelsIn(int block) const;      // FRAGMENT_BLOCK² but at the cut-off edges
};

// The camera paths the blocks hold in all: each block's samples times its pixels.
std::uint64_t pathsIn(const AdaptiveBlocks& blocks, std::span<const std::uint64_t> blockSamples);

// Each block's samples from an AdaptiveState's per pixel (top row first; the blocks in GL's rows,
// bottom first, as blockOf counts them). Throws std::invalid_argument when the size is not the
// image's or naming the first pixel (x, y from the top) whose count is not its block's.
std::vector<std::uint64_t> blockSamplesOf(const AdaptiveBlocks& blocks, std::span<const std::uint32_t> samples);

// Per block: its noise per sample and its cost, its pixels' mean rays per sample. The noise is the
// deviation per sample that would leave the block's mean with the error it has: the root of n
// times the error² of the mean, estimated as the mean over its pixels and R, G, B of (all − half)²
// scaled by h/(n − h), h the half's samples (adaptive_sampling.glsl; for independent samples
// E[(all − half)²] = σ²·(n − h)/(n·h)). From the running mean (RGBA per pixel), the tracer's half
// image (the half's mean, then rays per sample) in the same row order, and each block's samples.
struct BlockNoise {
    std::vector<double> deviation;
    std::vector<double> cost;
};
BlockNoise blockNoise(const AdaptiveBlocks& blocks, std::span<const float> meanRgba, std::span<const float> halfRgba,
                      std::span<const std::uint64_t> samples);

// Which blocks take the next pass (1) and which sit it out (0), from each block's deviation s (as
// blockNoise gives it: e·√n, e the estimated error of its mean), its cost c (rays per sample, at
// least 1) and the samples n it holds. While a block holds fewer than
// kAdaptiveWarmupSamples, all take it. Then a block takes it when s/(n·√c) (s floored at
// kAdaptiveDeviationFloor of the mean s) is at least the mean of that over the blocks: the image's
// MSE is the mean of e² = s²/n, so per unit of time a sample lowers it most where s²/(n²·c) is largest,
// and at the fixed point n ∝ s/√c, the spreading that minimises the MSE for the time spent
// (minimise Σ s²/n with Σ n·c fixed). At least one block always takes the pass.
std::vector<std::uint8_t> activeBlocks(std::span<const double> deviation, std::span<const double> cost,
                                       std::span<const std::uint64_t> samples);

// How many rounds of the pass's samples each block takes (0: it sits the pass out): activeBlocks
// decides who takes it, and a block whose s/(n·√c) is k times the mean takes k rounds (at most
// kAdaptiveMaxRounds), so that one far behind (a lamp's edge) catches up in fewer passes; never
// more paths in all than an even pass (bench/adaptive_sampling.md, "Rounds").
constexpr std::uint64_t kAdaptiveMaxRounds = 8;
std::vector<std::uint8_t> passRounds(const AdaptiveBlocks& blocks, std::span<const double> deviation,
                                     std::span<const double> cost, std::span<const std::uint64_t> samples);

// What the best spreading would gain over even spreading, per unit of time: the image's MSE with
// n ∝ s/√c over the MSE with every block taking every pass, mean(s²)·mean(c) / mean(s·√c)² (at
// least 1, by Cauchy–Schwarz; minimise Σ s²/n with Σ n·c fixed). From blockNoise's deviations and costs.
double adaptiveGain(std::span<const double> deviation, std::span<const double> cost);

// Below this gain every block takes every pass, as without adaptive sampling: the estimated s are
// noisy and an uneven pass costs more per sample, so a small gain on paper is a loss in time
// (the threshold's measurement: bench/adaptive_sampling.md, "Third version").
constexpr double kAdaptiveMinGain = 2.5;

// The gain changes slowly with the samples, and reading it costs two image read-backs
// (bench/adaptive_sampling.md, "On by default"): once it is found below kAdaptiveMinGain, it is
// read again only when the samples per pixel have grown by this factor.
constexpr double kAdaptiveGateRecheckGrowth = 1.25;

// A pass that only some blocks take would be a pass's fixed costs (its draws, the plan's read-back)
// for less work: each round of it takes the pass's samples this many times over, the image's pixels
// over the paths of one sample per round (`rounds`: passRounds, or 0/1 flags) rounded down, at most
// kAdaptiveMaxPassScale, so that a pass traces nearly as many samples as an even one and never more.
constexpr std::uint64_t kAdaptiveMaxPassScale = 8;
std::uint64_t passScale(const AdaptiveBlocks& blocks, std::span<const std::uint8_t> rounds);

} // namespace raylab
