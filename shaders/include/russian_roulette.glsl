// Russian roulette (Arvo & Kirk 1990; pbrt-v3 §13.7) with one random number per path. A bounce
// survives with probability q, and survivors divide their throughput by q. Instead of a fresh
// number per bounce, the path draws u once and survives bounce k while u < Q_k = q_1 ⋯ q_k: the
// q's are functions of the path so far, which u does not steer, so P(survive k | survived k − 1)
// = Q_k / Q_(k−1) = q_k, the per-bounce law exactly, and every sample's path length has the same
// distribution as with independent coins. What changes is stratification: the path's length is a
// step function of one well-stratified dimension instead of a product of coins from dimensions
// the sampler keeps independent (sampler.glsl's padded blocks), so its variance falls as fast as
// a one-dimensional integral's (bench/samplers.md, "Russian roulette from one number"). u has
// 24 bits, so a bounce whose Q is below 2^-24 survives with 2^-24 rather than Q, as a per-bounce
// coin's q would be rounded to 2^-24: a bias of at most 2^-24 of the radiance per bounce.
#ifndef RAYLAB_RUSSIAN_ROULETTE_GLSL
#define RAYLAB_RUSSIAN_ROULETTE_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

// q: the fourth root of the largest throughput component, at most 0.95 (pbrt-v3's cap), so Q_k
// strictly falls. After a survival beta is about the bounce's albedo, so q = beta itself (pbrt's;
// Cycles takes its square root) ends paths in a bright closed room at every bounce; the power is
// chosen by time to error (bench/samplers.md, "The roulette's survival probability").
RL_FN float rouletteProbability(vec3 beta) { return min(sqrt(sqrt(max(beta.r, max(beta.g, beta.b)))), 0.95f); }

// One bounce's roulette with the path's number u: `survival` (Q, 1 at the path's start) takes
// this bounce's q; true when the path goes on. A NaN q survives (the NaN guard counts it).
RL_FN bool rouletteSurvives(float u, float q, RL_INOUT(float) survival) {
    survival *= q;
    return !(u >= survival);
}

RL_NAMESPACE_END
#endif
