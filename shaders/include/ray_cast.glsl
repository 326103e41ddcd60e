// Records of the ray-rate benchmark (src/bench/ray_rate.h, shaders/entry/ray_cast.frag): rays in,
// nearest hits out, std430 and identical in C++. Shared by C++ and GLSL.
#ifndef RAYLAB_RAY_CAST_GLSL
#define RAYLAB_RAY_CAST_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

struct CastRay {
    vec4 originTMin;   // xyz origin; w tmin, always 0: raylab's traversal searches (0, tmax)
    vec4 dirTMax;      // xyz direction, unit; w tmax
};

struct CastHit {
    float t;           // distance to the nearest hit, CAST_MISS for none
    uint instance;     // raylab: top-level instance; Embree: geometry id
    uint primitive;    // raylab: sphere or global triangle index; Embree: primitive id
    uint unused;
};

const float CAST_MISS = -1.0f;

RL_NAMESPACE_END
#endif
