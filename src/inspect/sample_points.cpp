#include "inspect/sample_points.h"

#include "shaders/include/sampler.glsl"

namespace raylab {

std::uint32_t samplePairDimension(SamplePair pair, int bounce, bool lens) {
    switch (pair) {
    case SamplePair::Lens: return glsl::SAMPLE_DIM_LENS;
    case SamplePair::Bsdf: return glsl::bsdfSampleDim(bounce, lens);
    case SamplePair::Light: return glsl::sampleDim(bounce, glsl::SAMPLE_BOUNCE_LIGHT);
    default: return glsl::SAMPLE_DIM_PIXEL;
    }
}

std::vector<glm::vec2> samplePoints(const SamplePointsQuery& q) {
    using namespace glsl;
    const uint dim = samplePairDimension(q.pair, q.bounce, q.lens);
    const uint count = std::max(q.spp, 1u);
    std::vector<glm::vec2> points;
    points.reserve(q.count);
    for (uint i = q.first; i < q.first + q.count; ++i) {
        // sample2D of sampler.glsl, its RAYLAB_SAMPLER branch chosen at run time.
        switch (q.sampler) {
        case SamplerKind::Stratified: points.push_back(stratifiedSample2D(q.pixel, i, dim, q.seed, count)); break;
        case SamplerKind::Sobol:
            points.emplace_back(sobolSample1D(q.pixel, i, dim, q.seed), sobolSample1D(q.pixel, i, dim + 1u, q.seed));
            break;
        case SamplerKind::ZSobol: points.push_back(zsobolSample2D(q.pixel, i, dim, q.seed, count)); break;
        default: {
            Rng rng = rngCreate(q.pixel, i, q.seed);
            for (uint d = 0; d < dim; ++d) rngNextFloat(rng);
            points.push_back(rngNext2(rng));
        }
        }
    }
    return points;
}

} // namespace raylab
