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
    std::vector<float> rows;   // GL's order: the bottom row first
    rows.reserve(std::size_t(w) * std::size_t(h));
    largest_ = 0;
    for (int y = h - 1; y >= 0; --y)
        for (int x = 0; x < w; ++x) {
            const std::uint64_t n = tracer.samplesAt(x, y);
            largest_ = std::max(largest_, n);
            rows.push_back(float(n));
        }
    glTextureSubImage2D(texture_, 0, 0, 0, w, h, GL_RED, GL_FLOAT, rows.data());
    return texture_;
}

} // namespace raylab
