#pragma once
// The 2D points a pixel's samples take in one dimension pair of the path layout (pixel, lens, a
// bounce's BSDF direction or light point: shaders/include/sampler.glsl), made by the GLSL sampler
// compiled into C++, for the viewer's sample-points plot.
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string_view>
#include <vector>

namespace raylab {

enum class SamplePair { Pixel, Lens, Bsdf, Light };
inline constexpr std::string_view kSamplePairNames[] = {"pixel", "lens", "BSDF direction", "light point"};

struct SamplePointsQuery {
    SamplerKind sampler = SamplerKind::Independent;
    glm::uvec2 pixel{0, 0};      // the shader's pixel: origin bottom-left, as gl_FragCoord
    std::uint32_t seed = 1;      // render.seed
    std::uint32_t spp = 64;      // render.spp: the strata of stratified, the block of zsobol
    SamplePair pair = SamplePair::Pixel;
    int bounce = 0;              // for Bsdf and Light
    bool lens = true;            // the tracer's RAYLAB_FEATURE_DOF: without a lens, bounce 0's Bsdf is the lens pair
    std::uint32_t first = 0;     // first sample index of the pixel
    std::uint32_t count = 64;    // samples
};

// The first dimension of the pair (the second is the next one).
std::uint32_t samplePairDimension(SamplePair pair, int bounce, bool lens);

// Points in [0, 1)² of samples first … first + count − 1, as the tracer compiled with
// query.sampler draws them; independent draws its numbers in call order, so its points are the
// stream's numbers at the pair's place when every earlier dimension was drawn once.
std::vector<glm::vec2> samplePoints(const SamplePointsQuery& query);

} // namespace raylab
