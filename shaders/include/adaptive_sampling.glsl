// Per-pixel adaptive sampling (render.adaptive): before each pass the host decides, per block of
// FRAGMENT_BLOCK × FRAGMENT_BLOCK pixels, whether the block takes the pass's samples, from each
// pixel's running mean, the running mean of half its samples and its rays per sample
// (render/adaptive_sampling.h). The plan image gives a pixel its samples so far, or ADAPTIVE_SKIP;
// the tracer keeps the half mean and the rays beside the mean. Shared by C++ and GLSL.
#ifndef RAYLAB_ADAPTIVE_SAMPLING_GLSL
#define RAYLAB_ADAPTIVE_SAMPLING_GLSL
#include "compat.glsl"
#include "bindings.glsl"
#include "features.glsl"
RL_NAMESPACE_BEGIN

const uint ADAPTIVE_SKIP = 0xffffffffu;   // a plan texel: the pixel's block sits this pass out

// The half: samples whose index lies in an even run of ADAPTIVE_HALF_RUN. Comparing all samples'
// mean with the half's estimates the error of the mean (Cycles' adaptive sampling compares all
// with every other sample): for independent samples E[(all − half)²]·h/(n − h) is the variance of
// the mean, h the half's samples. Runs of 8 rather than every other sample: bench/adaptive_sampling.md,
// "Second version", compares the two.
const uint ADAPTIVE_HALF_RUN = 8u;
RL_FN bool adaptiveInHalf(uint index) { return (index & ADAPTIVE_HALF_RUN) == 0u; }
// Samples of the half among indices [0, n).
RL_FN uint adaptiveHalfCount(uint n) {
    return (n / (2u * ADAPTIVE_HALF_RUN)) * ADAPTIVE_HALF_RUN + min(n % (2u * ADAPTIVE_HALF_RUN), ADAPTIVE_HALF_RUN);
}

RL_NAMESPACE_END

#if !defined(__cplusplus) && RAYLAB_ADAPTIVE
layout(r32ui, binding = BINDING_SAMPLE_PLAN_IMAGE) readonly uniform uimage2D uSamplePlan;
// Running means: of the half's samples (rgb) and of the rays traced per sample (a).
layout(rgba32f, binding = BINDING_ADAPTIVE_HALF_IMAGE) uniform image2D uAdaptiveHalf;
// The blocks the draw traces, slot by slot of its strip (params.fragmentStripBlocks of them).
layout(std430, binding = BINDING_ADAPTIVE_BLOCKS) readonly buffer AdaptiveBlocks { uint adaptiveBlocks[]; };
#endif

#endif
