// Per-pixel adaptive sampling (render.adaptive): before each pass the host decides, per block of
// FRAGMENT_BLOCK × FRAGMENT_BLOCK pixels, whether the block takes the pass's samples, from each
// pixel's running mean, second moment and rays per sample (render/adaptive_sampling.h). The plan
// image gives a pixel its samples so far, or ADAPTIVE_SKIP; the tracer keeps the moments beside the mean.
// Shared by C++ and GLSL.
#ifndef RAYLAB_ADAPTIVE_SAMPLING_GLSL
#define RAYLAB_ADAPTIVE_SAMPLING_GLSL
#include "compat.glsl"
#include "bindings.glsl"
#include "features.glsl"
RL_NAMESPACE_BEGIN

const uint ADAPTIVE_SKIP = 0xffffffffu;   // a plan texel: the pixel's block sits this pass out

// The value whose second moment the host reads: the mean of R, G and B, as the benchmark's MSE
// averages its channels.
RL_FN float adaptiveValue(vec3 L) { return (L.r + L.g + L.b) * (1.0f / 3.0f); }

RL_NAMESPACE_END

#if !defined(__cplusplus) && RAYLAB_ADAPTIVE
layout(r32ui, binding = BINDING_SAMPLE_PLAN_IMAGE) readonly uniform uimage2D uSamplePlan;
// Running means per sample: of adaptiveValue² (r) and of the rays traced (g).
layout(rg32f, binding = BINDING_SECOND_MOMENT_IMAGE) uniform image2D uSecondMoment;
#endif

#endif
