#pragma once
// The "samples" debug view's image: each pixel's samples so far (PathTracer::pixelSamples) as a
// one-channel float texture, bottom row first as the tracer's images, which the display pass draws
// as a heat map. Adaptive sampling's plan made visible: its blocks' counts differ; even spreading
// gives one colour. Needs a current GL 4.5 context.
#include <cstdint>

namespace raylab {

class PathTracer;

class SampleCountTexture {
public:
    SampleCountTexture() = default;
    ~SampleCountTexture();
    SampleCountTexture(const SampleCountTexture&) = delete;
    SampleCountTexture& operator=(const SampleCountTexture&) = delete;

    // Uploads the tracer's counts as they are now and returns the texture (R32F, the tracer's size).
    unsigned update(const PathTracer& tracer);
    // The largest count of the last update: the heat map's red when scaled automatically.
    std::uint64_t largest() const { return largest_; }

private:
    unsigned texture_ = 0;
    int width_ = 0;
    int height_ = 0;
    std::uint64_t largest_ = 0;
};

} // namespace raylab
