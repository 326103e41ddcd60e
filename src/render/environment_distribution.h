#pragma once
// Importance sampling of an equirectangular sky image: a piecewise-constant 2D distribution over
// its texels, proportional to max(r, g, b) × sinθ of the texel's row (the solid angle a texel
// covers), sampled as a marginal over rows and a conditional over the columns of the chosen row
// (pbrt-v4 PiecewiseConstant2D, §A.5). The GPU copy of the tables is searched in
// shaders/include/environment_sampling.glsl, which must stay in step with sample() here.
#include "render/image.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

class EnvironmentDistribution {
public:
    EnvironmentDistribution() = default;
    explicit EnvironmentDistribution(const Image& map);

    int width() const { return width_; }
    int height() const { return height_; }
    // Mean texel weight; 0 for a black map (then nothing can be sampled).
    float meanWeight() const { return mean_; }
    // Cumulative tables, normalised to end at 1: marginal has height + 1 entries, the
    // conditional one width + 1 entries per row, rows one after the other.
    const std::vector<float>& marginalCdf() const { return marginal_; }
    const std::vector<float>& conditionalCdf() const { return conditional_; }

    // Texel weight as the distribution sees it.
    static float texelWeight(glm::vec3 radiance, int row, int height);

    // (u, v) in [0, 1)² with density pdfUv; uniform within the chosen texel.
    glm::vec2 sample(glm::vec2 u, float& pdfUv) const;
    float pdfUv(glm::vec2 uv) const;

private:
    int width_ = 0;
    int height_ = 0;
    float mean_ = 0.0f;
    std::vector<float> weights_;
    std::vector<float> marginal_;
    std::vector<float> conditional_;
};

} // namespace raylab
