#pragma once
// Random numbers for the numerical stress tests, from the shader's own generator (random.glsl).
#include "shaders/include/random.glsl"

#include <algorithm>
#include <cmath>

namespace raylab::test {

struct StressSampler {
    glsl::Rng rng;
    float next() { return glsl::rngNextFloat(rng); }
    glm::vec2 next2() { return glsl::rngNext2(rng); }
    // Log-uniform in [lo, hi].
    float logUniform(float lo, float hi) { return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * next()); }
    glm::vec3 unitVector() {
        const glm::vec2 u = next2();
        const float z = 1 - 2 * u.x, s = std::sqrt(std::max(0.0f, 1 - z * z));
        return glm::vec3(s * std::cos(2 * glsl::PI * u.y), s * std::sin(2 * glsl::PI * u.y), z);
    }
};

} // namespace raylab::test
