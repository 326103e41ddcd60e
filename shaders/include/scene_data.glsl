// The host contract of the path tracer: every buffer and uniform the tracer reads, with the
// binding points render/path_tracer.cpp and render/gpu_scene.cpp use. GLSL only.
#ifndef RAYLAB_SCENE_DATA_GLSL
#define RAYLAB_SCENE_DATA_GLSL
#include "features.glsl"
#include "scene_types.glsl"
#include "analytic_lights.glsl"
#include "bindings.glsl"

layout(rgba32f, binding = BINDING_ACCUM_IMAGE) uniform image2D uAccum;   // running mean, rgb; a = 1
layout(std430, binding = BINDING_SPHERES) readonly buffer SphereBuffer { GpuSphere spheres[]; };
layout(std430, binding = BINDING_MATERIALS) readonly buffer MaterialBuffer { GpuMaterial materials[]; };
layout(binding = BINDING_MATERIAL_TEXELS) uniform usamplerBuffer materialTexels;   // the same buffer's bits

// A hit's material: the three vec4s every bounce reads through the texel view, one fetch gathering
// eight lanes where the storage-buffer load walks them one by one (bench/mesh_rays.md); the texture
// fields, which only textured variants read, from the buffer.
GpuMaterial materialAt(uint i) {
    GpuMaterial m = materials[i];
    int b = int(MATERIAL_TEXELS * i);
    m.albedo = uintBitsToFloat(texelFetch(materialTexels, b));
    m.emission = uintBitsToFloat(texelFetch(materialTexels, b + 1));
    m.f0Ior = uintBitsToFloat(texelFetch(materialTexels, b + 2));
    return m;
}
layout(std430, binding = BINDING_COUNTERS) buffer CounterBuffer {
    uint nonFiniteSamples;   // samples that were NaN or Inf and were replaced by 0
    uint raysTraced;         // ray casts this pass (camera and bounce rays)
    uint loopLimited;        // invocations whose loops the driver cut short (path_tracer.glsl)
};

layout(std430, binding = BINDING_SPHERE_LIGHTS) readonly buffer LightBuffer { GpuLight lights[]; };
layout(binding = BINDING_SKY_MAP_TEXTURE) uniform sampler2D uSkyMap;   // sky.map (1×1 black without)
// Buffers of optional features are declared only with their feature: llvmpipe allows 16 storage
// blocks per stage, and the debug variants (heat maps) add their own.
#if RAYLAB_SKY_MAP
// Sky map importance sampling (render/environment_distribution.h): marginal CDF over rows
// (height + 1 floats), conditional CDFs over columns (height × (width + 1) floats).
layout(std430, binding = BINDING_ENV_MARGINAL) readonly buffer EnvMarginalBuffer { float envMarginalCdf[]; };
layout(std430, binding = BINDING_ENV_CONDITIONAL) readonly buffer EnvConditionalBuffer { float envConditionalCdf[]; };
#endif
// The light buffers are read through texture-buffer views: the reads' indices differ between
// lanes, and llvmpipe gathers a texel for eight lanes where a storage-buffer record is eight lane
// loops per component (bench/mesh_rays.md, "The light records through texel views").
#if RAYLAB_EMISSIVE_TRIANGLES
// Emissive triangles in world space (render/light_list.h), GpuTriangleLight records of 4 texels.
layout(binding = BINDING_TRIANGLE_LIGHT_TEXELS) uniform usamplerBuffer triangleLightTexels;
GpuTriangleLight triangleLightAt(int j) {
    int b = int(TRIANGLE_LIGHT_TEXELS) * j;
    return GpuTriangleLight(uintBitsToFloat(texelFetch(triangleLightTexels, b)),
                            uintBitsToFloat(texelFetch(triangleLightTexels, b + 1)),
                            uintBitsToFloat(texelFetch(triangleLightTexels, b + 2)),
                            uintBitsToFloat(texelFetch(triangleLightTexels, b + 3)));
}
#endif
#if RAYLAB_EMISSIVE_TRIANGLES || RAYLAB_ONE_SIDED_EMITTERS
// Per triangle (global index): 1 + its index among the triangle lights, 0 when it is no light;
// with TRIANGLE_FRONT_ONLY set when it emits on the front alone.
layout(binding = BINDING_TRIANGLE_LIGHT_INDEX_TEXELS) uniform usamplerBuffer triangleLightIndexTexels;
uint triangleLightIndexAt(uint triangle) { return texelFetch(triangleLightIndexTexels, int(triangle)).r; }
#endif
#if RAYLAB_ANALYTIC_LIGHTS
// Point, spot and distant lights (render/light_list.h), in a uniform block: no storage block is free.
layout(std140, binding = BINDING_ANALYTIC_LIGHTS_UBO) uniform AnalyticLightBlock {
    ivec4 analyticLightInfo;   // x: lights in use
    GpuAnalyticLight analyticLights[MAX_ANALYTIC_LIGHTS];
};
#endif
#if RAYLAB_LIGHT_POWER_SELECTION
// The alias table that picks any light (spheres first, then triangles) by power: (q, alias, pmf,
// pmf of alias) per light (render/light_list.h).
layout(binding = BINDING_LIGHT_ALIAS_TEXELS) uniform usamplerBuffer lightAliasTexels;
vec4 lightAliasAt(int i) { return uintBitsToFloat(texelFetch(lightAliasTexels, i)); }
#endif

// Every other parameter of the tracer, one uniform block.
#include "tracer_params.glsl"

#endif
