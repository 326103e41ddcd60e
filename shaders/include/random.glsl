// Per-sample random numbers: a PCG hash seeds a PCG-RXS-M-XS 32-bit stream.
// Hashes from Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020.
#ifndef RAYLAB_RANDOM_GLSL
#define RAYLAB_RANDOM_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

// pcg4d: a 4D → 4D hash with good avalanche; used to decorrelate (pixel, sample, seed).
RL_FN uvec4 pcg4d(uvec4 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.w; v.y += v.z * v.x; v.z += v.x * v.y; v.w += v.y * v.z;
    v = v ^ (v >> 16u);
    v.x += v.y * v.w; v.y += v.z * v.x; v.z += v.x * v.y; v.w += v.y * v.z;
    return v;
}

struct Rng {
    uint state;
};

// One independent stream per (pixel, sample index, seed): the image is reproducible bit for bit
// and does not depend on how samples are split into passes.
RL_FN Rng rngCreate(uvec2 pixel, uint sampleIndex, uint seed) {
    uvec4 h = pcg4d(uvec4(pixel.x, pixel.y, sampleIndex, seed));
    return Rng(h.x ^ h.z);
}

// PCG-RXS-M-XS 32 (O'Neill 2014): LCG step, then a permutation of the old state.
RL_FN uint rngNextUint(RL_INOUT(Rng) rng) {
    uint s = rng.state;
    rng.state = s * 747796405u + 2891336453u;
    uint word = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
    return (word >> 22u) ^ word;
}

// Uniform in [0, 1): the top 24 bits, so 1.0 is never returned.
RL_FN float rngNextFloat(RL_INOUT(Rng) rng) {
    return float(rngNextUint(rng) >> 8u) * (1.0f / 16777216.0f);
}

RL_FN vec2 rngNext2(RL_INOUT(Rng) rng) {
    float a = rngNextFloat(rng);
    float b = rngNextFloat(rng);
    return vec2(a, b);
}

RL_NAMESPACE_END
#endif
