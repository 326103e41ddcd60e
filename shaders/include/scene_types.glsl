// GPU-side scene records, laid out for std430 buffers and identical in C++ (only vec4 / uvec4
// members, so both languages agree on size and alignment: 16-byte records).
#ifndef RAYLAB_SCENE_TYPES_GLSL
#define RAYLAB_SCENE_TYPES_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

struct GpuSphere {
    vec4 centerRadius;   // xyz centre, w radius
    uvec4 info;          // x material index; yzw unused
};

struct GpuMaterial {
    vec4 albedo;     // rgb diffuse reflectance, a unused
    vec4 emission;   // rgb emitted radiance (colour × strength), a unused
};

RL_NAMESPACE_END
#endif
