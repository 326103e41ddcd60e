#include "render/environment_distribution.h"

#include <algorithm>
#include <cmath>

namespace raylab {

float EnvironmentDistribution::texelWeight(glm::vec3 radiance, int row, int height) {
    const float theta = (float(row) + 0.5f) / float(height) * 3.14159265358979f;
    return std::max({radiance.r, radiance.g, radiance.b, 0.0f}) * std::sin(theta);
}

EnvironmentDistribution::EnvironmentDistribution(const Image& map)
    : width_(map.width), height_(map.height), weights_(size_t(map.width) * size_t(map.height)),
      marginal_(size_t(map.height) + 1, 0.0f), conditional_(size_t(map.height) * size_t(map.width + 1), 0.0f) {
    double total = 0.0;
    std::vector<double> rowSums(size_t(height_), 0.0);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const float w = texelWeight(map.rgb(x, y), y, height_);
            weights_[size_t(y * width_ + x)] = w;
            rowSums[size_t(y)] += w;
        }
    for (double s : rowSums) total += s;
    mean_ = float(total / (double(width_) * height_));
    for (int y = 0; y < height_; ++y) {
        float* cdf = &conditional_[size_t(y) * size_t(width_ + 1)];
        double acc = 0.0;
        for (int x = 0; x < width_; ++x) {
            acc += weights_[size_t(y * width_ + x)];
            // A black row gets a uniform conditional, which is never chosen anyway.
            cdf[x + 1] = rowSums[size_t(y)] > 0.0 ? float(acc / rowSums[size_t(y)]) : float(x + 1) / float(width_);
        }
        cdf[width_] = 1.0f;
        if (total > 0.0) marginal_[size_t(y) + 1] = marginal_[size_t(y)] + float(rowSums[size_t(y)] / total);
    }
    marginal_[size_t(height_)] = total > 0.0 ? 1.0f : 0.0f;
}

namespace {

// The last index i with cdf[i] <= u, searched among the n + 1 entries of cdf (as in the shader).
int findInterval(const float* cdf, int n, float u) {
    int lo = 0, hi = n;   // invariant: cdf[lo] <= u < cdf[hi] (cdf[n] = 1 > u)
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (cdf[mid] <= u) lo = mid;
        else hi = mid;
    }
    return lo;
}

} // namespace

glm::vec2 EnvironmentDistribution::sample(glm::vec2 u, float& pdf) const {
    const int y = findInterval(marginal_.data(), height_, u.y);
    const float* row = &conditional_[size_t(y) * size_t(width_ + 1)];
    const int x = findInterval(row, width_, u.x);
    // Reuse the random numbers within the chosen cells (stays uniform in the texel).
    const float dy = marginal_[size_t(y) + 1] - marginal_[size_t(y)];
    const float dx = row[x + 1] - row[x];
    const float fy = dy > 0.0f ? std::clamp((u.y - marginal_[size_t(y)]) / dy, 0.0f, 0.99999994f) : 0.5f;
    const float fx = dx > 0.0f ? std::clamp((u.x - row[x]) / dx, 0.0f, 0.99999994f) : 0.5f;
    const glm::vec2 uv((float(x) + fx) / float(width_), (float(y) + fy) / float(height_));
    pdf = pdfUv(uv);
    return uv;
}

float EnvironmentDistribution::pdfUv(glm::vec2 uv) const {
    if (mean_ <= 0.0f) return 0.0f;
    const int x = std::clamp(int(uv.x * float(width_)), 0, width_ - 1);
    const int y = std::clamp(int(uv.y * float(height_)), 0, height_ - 1);
    return weights_[size_t(y * width_ + x)] / mean_;
}

} // namespace raylab
