#include "render/sample_count_texture.h"

#include "render/path_tracer.h"

#include <glad/gl.h>

#include <algorithm>
#include <vector>

namespace raylab {

SampleCountTexture::~SampleCountTexture() {
    if (texture_) glDeleteTextures(1, &texture_);
}

unsigned SampleCountTexture::update(const PathTracer& tracer) {
    const int w = tracer.width(), h = tracer.height();
    if (!texture_ || w != width_ || h != height_) {
        if (texture_) glDeleteTextures(1, &texture_);
        glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
        glTextureStorage2D(texture_, 1, GL_R32F, w, h);
        width_ = w;
        height_ = h;
    }
    const std::vector<std::uint64_t> samples = tracer.pixelSamples();   // top row first
    std::vector<float> rows(samples.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            rows[std::size_t(h - 1 - y) * std::size_t(w) + std::size_t(x)] =
                float(samples[std::size_t(y) * std::size_t(w) + std::size_t(x)]);
    largest_ = samples.empty() ? 0 : *std::max_element(samples.begin(), samples.end());
    glTextureSubImage2D(texture_, 0, 0, 0, w, h, GL_RED, GL_FLOAT, rows.data());
    return texture_;
}

} // namespace raylab
