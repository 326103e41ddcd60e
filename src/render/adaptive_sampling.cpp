#include "render/adaptive_sampling.h"

#include "shaders/include/adaptive_sampling.glsl"
#include "shaders/include/fragment_layout.glsl"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace raylab {

static_assert(kAdaptiveWarmupSamples >= 2 * glsl::ADAPTIVE_HALF_RUN,
              "the first decision needs samples in the half and in the other half");

int AdaptiveBlocks::columns() const { return (width + glsl::FRAGMENT_BLOCK - 1) / glsl::FRAGMENT_BLOCK; }
int AdaptiveBlocks::rows() const { return (height + glsl::FRAGMENT_BLOCK - 1) / glsl::FRAGMENT_BLOCK; }
int AdaptiveBlocks::blockOf(int x, int y) const {
    return (y / glsl::FRAGMENT_BLOCK) * columns() + x / glsl::FRAGMENT_BLOCK;
}
int AdaptiveBlocks::pixelsIn(int block) const {
    const int x = (block % columns()) * glsl::FRAGMENT_BLOCK, y = (block / columns()) * glsl::FRAGMENT_BLOCK;
    return std::min(glsl::FRAGMENT_BLOCK, width - x) * std::min(glsl::FRAGMENT_BLOCK, height - y);
}

std::uint64_t pathsIn(const AdaptiveBlocks& blocks, std::span<const std::uint64_t> blockSamples) {
    std::uint64_t paths = 0;
    for (std::size_t b = 0; b < blockSamples.size(); ++b)
        paths += blockSamples[b] * std::uint64_t(blocks.pixelsIn(int(b)));
    return paths;
}

std::vector<std::uint64_t> blockSamplesOf(const AdaptiveBlocks& blocks, std::span<const std::uint32_t> samples) {
    if (samples.size() != std::size_t(blocks.width) * std::size_t(blocks.height))
        throw std::invalid_argument(std::to_string(samples.size()) + " sample counts for an image of " +
                                    std::to_string(blocks.width) + "x" + std::to_string(blocks.height) + " pixels");
    std::vector<std::uint64_t> counts(std::size_t(blocks.count()));
    std::vector<bool> seen(counts.size(), false);
    for (int y = 0; y < blocks.height; ++y)
        for (int x = 0; x < blocks.width; ++x) {
            const std::uint64_t n = samples[std::size_t(y) * std::size_t(blocks.width) + std::size_t(x)];
            const std::size_t b = std::size_t(blocks.blockOf(x, blocks.height - 1 - y));
            if (!seen[b]) {
                seen[b] = true;
                counts[b] = n;
            } else if (counts[b] != n) {
                throw std::invalid_argument("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") holds " +
                                            std::to_string(n) + " samples, another pixel of its " +
                                            std::to_string(glsl::FRAGMENT_BLOCK) + "x" +
                                            std::to_string(glsl::FRAGMENT_BLOCK) + " block " +
                                            std::to_string(counts[b]) + " (a block shares one count)");
            }
        }
    return counts;
}

BlockNoise blockNoise(const AdaptiveBlocks& blocks, std::span<const float> meanRgba, std::span<const float> halfRgba,
                      std::span<const std::uint64_t> samples) {
    const std::size_t pixels = std::size_t(blocks.width) * std::size_t(blocks.height);
    if (meanRgba.size() != 4 * pixels || halfRgba.size() != 4 * pixels)
        throw std::invalid_argument("blockNoise: the images are not the blocks' size");
    const std::size_t n = std::size_t(blocks.count());
    if (samples.size() != n) throw std::invalid_argument("blockNoise: one sample count per block");
    std::vector<double> difference(n, 0.0), rays(n, 0.0);
    for (int y = 0; y < blocks.height; ++y)
        for (int x = 0; x < blocks.width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(blocks.width) + std::size_t(x);
            const std::size_t b = std::size_t(blocks.blockOf(x, y));
            for (std::size_t c = 0; c < 3; ++c) {
                const double d = double(meanRgba[4 * i + c]) - double(halfRgba[4 * i + c]);
                if (std::isfinite(d)) difference[b] += d * d / 3.0;
            }
            if (std::isfinite(halfRgba[4 * i + 3])) rays[b] += double(halfRgba[4 * i + 3]);
        }
    BlockNoise noise{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
    for (std::size_t b = 0; b < n; ++b) {
        const double pixelsIn = double(blocks.pixelsIn(int(b)));
        noise.cost[b] = rays[b] / pixelsIn;
        const std::uint64_t all = samples[b];
        const std::uint64_t half = glsl::adaptiveHalfCount(unsigned(std::min<std::uint64_t>(all, 0xffffffffu)));
        if (half == 0 || half >= all) continue;   // no second set to compare with yet
        const double meanError2 = difference[b] / pixelsIn * double(half) / double(all - half);
        noise.deviation[b] = std::sqrt(double(all) * meanError2);
    }
    return noise;
}

namespace {

double meanOf(std::span<const double> v) {
    double sum = 0.0;
    for (double x : v) sum += x;
    return sum / double(v.size());
}

// Each block's s/(n·√c), its deviation at least kAdaptiveDeviationFloor of the mean block's; a
// sample traces at least its camera ray.
std::vector<double> behindRatios(std::span<const double> deviation, std::span<const double> cost,
                                 std::span<const std::uint64_t> samples) {
    const double floor = kAdaptiveDeviationFloor * meanOf(deviation);
    std::vector<double> ratio(samples.size());
    for (std::size_t b = 0; b < samples.size(); ++b)
        ratio[b] = std::max(deviation[b], floor) / (double(samples[b]) * std::sqrt(std::max(cost[b], 1.0)));
    return ratio;
}

// activeBlocks from the blocks' ratios, after the warm-up.
std::vector<std::uint8_t> atOrAboveTheMean(const std::vector<double>& ratio, double meanRatio) {
    // Where the ratios are all alike (a furnace: no variance anywhere) every block takes the pass,
    // the mean's rounding aside.
    const double threshold = meanRatio * (1.0 - 1e-9);
    std::vector<std::uint8_t> active(ratio.size());
    for (std::size_t b = 0; b < ratio.size(); ++b) active[b] = ratio[b] >= threshold ? 1 : 0;
    if (std::find(active.begin(), active.end(), 1) == active.end())   // rounding: the largest ratio takes it
        active[std::size_t(std::max_element(ratio.begin(), ratio.end()) - ratio.begin())] = 1;
    return active;
}

bool warmingUp(std::span<const std::uint64_t> samples) {
    return samples.empty() || *std::min_element(samples.begin(), samples.end()) < kAdaptiveWarmupSamples;
}

} // namespace

std::vector<std::uint8_t> activeBlocks(std::span<const double> deviation, std::span<const double> cost,
                                       std::span<const std::uint64_t> samples) {
    if (deviation.size() != samples.size() || cost.size() != samples.size())
        throw std::invalid_argument("activeBlocks: one deviation and cost per block");
    if (warmingUp(samples)) return std::vector<std::uint8_t>(samples.size(), 1);
    const std::vector<double> ratio = behindRatios(deviation, cost, samples);
    return atOrAboveTheMean(ratio, meanOf(ratio));
}

std::vector<std::uint8_t> passRounds(const AdaptiveBlocks& blocks, std::span<const double> deviation,
                                     std::span<const double> cost, std::span<const std::uint64_t> samples) {
    if (deviation.size() != samples.size() || cost.size() != samples.size() ||
        samples.size() != std::size_t(blocks.count()))
        throw std::invalid_argument("passRounds: one deviation, cost and count per block");
    if (warmingUp(samples)) return std::vector<std::uint8_t>(samples.size(), 1);
    const std::vector<double> ratio = behindRatios(deviation, cost, samples);
    const double meanRatio = meanOf(ratio);
    std::vector<std::uint8_t> rounds = atOrAboveTheMean(ratio, meanRatio);
    if (!(meanRatio > 0.0)) return rounds;   // no variance anywhere: one round each
    std::uint64_t paths = 0, pixels = 0;
    for (std::size_t b = 0; b < samples.size(); ++b) {
        if (rounds[b])
            rounds[b] = std::uint8_t(std::clamp(std::floor(ratio[b] / meanRatio), 1.0, double(kAdaptiveMaxRounds)));
        paths += std::uint64_t(rounds[b]) * std::uint64_t(blocks.pixelsIn(int(b)));
        pixels += std::uint64_t(blocks.pixelsIn(int(b)));
    }
    if (paths > pixels)   // never more paths than an even pass
        for (std::uint8_t& r : rounds)
            if (r > 1) r = std::uint8_t(std::max<std::uint64_t>(1, std::uint64_t(r) * pixels / paths));
    return rounds;
}

double adaptiveGain(std::span<const double> deviation, std::span<const double> cost) {
    if (deviation.size() != cost.size()) throw std::invalid_argument("adaptiveGain: one deviation and cost per block");
    double s2 = 0.0, c = 0.0, sc = 0.0;
    for (std::size_t b = 0; b < deviation.size(); ++b) {
        const double cb = std::max(cost[b], 1.0);   // as activeBlocks: a sample traces at least its camera ray
        s2 += deviation[b] * deviation[b];
        c += cb;
        sc += deviation[b] * std::sqrt(cb);
    }
    if (!(sc > 0.0)) return 1.0;   // no variance anywhere: nothing to gain
    const double n = double(deviation.size());
    return (s2 / n) * (c / n) / ((sc / n) * (sc / n));
}

std::uint64_t passScale(const AdaptiveBlocks& blocks, std::span<const std::uint8_t> rounds) {
    if (rounds.size() != std::size_t(blocks.count())) throw std::invalid_argument("passScale: one count per block");
    std::uint64_t paths = 0;
    for (std::size_t b = 0; b < rounds.size(); ++b)
        paths += std::uint64_t(rounds[b]) * std::uint64_t(blocks.pixelsIn(int(b)));
    if (paths == 0) return 1;
    const std::uint64_t pixels = std::uint64_t(blocks.width) * std::uint64_t(blocks.height);
    return std::clamp<std::uint64_t>(pixels / paths, 1, kAdaptiveMaxPassScale);
}

} // namespace raylab
