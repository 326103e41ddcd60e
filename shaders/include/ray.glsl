// Rays, and leaving a surface without hitting it again.
#ifndef RAYLAB_RAY_GLSL
#define RAYLAB_RAY_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

struct Ray {
    vec3 origin;
    vec3 dir;   // not necessarily unit length
};

RL_FN vec3 rayAt(Ray r, float t) { return r.origin + t * r.dir; }

// Float rounding unit, 2^-24, and Higham's γ(n) = n·u / (1 − n·u), the bound on the relative
// error of n chained float operations (pbrt-v4 §6.8.1).
const float ROUNDING_UNIT = 5.9604645e-8f;
RL_FN float gammaBound(float n) { return (n * ROUNDING_UNIT) / (1.0f - n * ROUNDING_UNIT); }

// One float step away from zero or towards it, in the direction of `towards`.
RL_FN float nextFloatToward(float v, float towards) {
    if (towards == 0.0f) return v;
    if (v == 0.0f) return towards > 0.0f ? 1.17549435e-38f : -1.17549435e-38f;
    bool away = (v > 0.0f) == (towards > 0.0f);
    return intBitsToFloat(floatBitsToInt(v) + (away ? 1 : -1));
}

// Moves a hit point p, whose coordinates are each known within ±pointError, off its surface to
// the side the geometric normal n points to, just far enough that the new ray cannot start
// behind the surface: along n by the error bound projected on n, then rounded one more float
// step away (pbrt-v4 OffsetRayOrigin, §6.8.6). Scales with the coordinates, no fixed epsilon.
RL_FN vec3 offsetRayOrigin(vec3 p, vec3 n, vec3 pointError) {
    float d = dot(abs(n), pointError);
    vec3 o = p + d * n;
    return vec3(nextFloatToward(o.x, n.x), nextFloatToward(o.y, n.y), nextFloatToward(o.z, n.z));
}

RL_NAMESPACE_END
#endif
