// The host contract of the path tracer: every buffer and uniform the tracer reads, with the
// binding points render/path_tracer.cpp and render/gpu_scene.cpp use. GLSL only.
#ifndef RAYLAB_SCENE_DATA_GLSL
#define RAYLAB_SCENE_DATA_GLSL
#include "features.glsl"
#include "scene_types.glsl"

layout(rgba32f, binding = 0) uniform image2D uAccum;   // running mean, rgb; a = 1
layout(std430, binding = 1) readonly buffer SphereBuffer { GpuSphere spheres[]; };
layout(std430, binding = 2) readonly buffer MaterialBuffer { GpuMaterial materials[]; };
layout(std430, binding = 3) buffer CounterBuffer {
    uint nonFiniteSamples;   // samples that were NaN or Inf and were replaced by 0
    uint raysTraced;         // ray casts this pass (camera and bounce rays)
};

layout(std430, binding = 4) readonly buffer LightBuffer { GpuLight lights[]; };
layout(binding = 4) uniform sampler2D uSkyMap;   // texture unit 4: sky.map (1×1 black without)
// Buffers of optional features are declared only with their feature: llvmpipe allows 16 storage
// blocks per stage, and the debug variants (heat maps) add their own.
#ifdef RAYLAB_SKY_MAP
// Sky map importance sampling (render/environment_distribution.h): marginal CDF over rows
// (height + 1 floats), conditional CDFs over columns (height × (width + 1) floats).
layout(std430, binding = 5) readonly buffer EnvMarginalBuffer { float envMarginalCdf[]; };
layout(std430, binding = 6) readonly buffer EnvConditionalBuffer { float envConditionalCdf[]; };
#endif
#ifdef RAYLAB_EMISSIVE_TRIANGLES
// Emissive triangles in world space (render/light_list.h).
layout(std430, binding = 24) readonly buffer TriangleLightBuffer { GpuTriangleLight triangleLights[]; };
// Per triangle (global index): 1 + its index in triangleLights[], 0 when it is no light.
layout(std430, binding = 26) readonly buffer TriangleLightIndexBuffer { uint triangleLightIndex[]; };
#endif
#ifdef RAYLAB_LIGHT_POWER_SELECTION
// The alias table that picks any light (spheres first, then triangles) by power: (q, alias, pmf,
// pmf of alias) per light (render/light_list.h).
layout(std430, binding = 25) readonly buffer LightAliasBuffer { vec4 lightAlias[]; };
#endif

// Every other parameter of the tracer, one uniform block.
#include "tracer_params.glsl"

#endif
