// Ray–box slab test robust to rounding, zero direction components and origins on slab planes
// (Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013; pbrt-v4 Bounds3::IntersectP). Shared by
// C++ and GLSL.
#ifndef RAYLAB_AABB_GLSL
#define RAYLAB_AABB_GLSL
#include "compat.glsl"
#include "ray.glsl"
RL_NAMESPACE_BEGIN

// 1/d per component, with components below 1e-30 in magnitude replaced by ±1e-30 first: GLSL does
// not promise IEEE infinities and may flush denormals, and a finite huge inverse never makes the
// NaN of 0·∞ when the origin lies on a slab plane (the slab then spans [0, huge] or [-huge, 0]).
RL_FN float safeInverse(float d) {
    const float tiny = 1e-30f;
    return 1.0f / (abs(d) < tiny ? (d < 0.0f ? -tiny : tiny) : d);
}

RL_FN vec3 safeInverseDir(vec3 d) { return vec3(safeInverse(d.x), safeInverse(d.y), safeInverse(d.z)); }

// Entry distance of the ray into the box within [0, tMax], or -1 for a miss. The box is closed:
// a ray running inside a face's plane (zero direction component, origin on the plane) is inside
// that slab. The planes are moved out by 1e-15 world units so such a difference is never an exact
// 0 (0 × huge would give a slab of one point); with direction components of ordinary size this
// changes t by ~1e-15 and only ever widens the box.
#ifdef RAYLAB_EXERCISE_SLAB_TEST
#include RAYLAB_EXERCISE_SLAB_TEST   // a pupil's intersectBox (exercises/README.md)
#else
RL_FN float intersectBox(vec3 origin, vec3 invDir, vec3 boxMin, vec3 boxMax, float tMax) {
    const float widen = 1e-15f;
    vec3 t0 = ((boxMin - origin) - vec3(widen)) * invDir;
    vec3 t1 = ((boxMax - origin) + vec3(widen)) * invDir;
    vec3 tNear = min(t0, t1);
    // Rounding in the subtractions and products can put tFar below the true value: widen it by
    // 2γ(3) (Ize 2013, §3; pbrt-v4 uses 1 + 2γ(3)).
    vec3 tFar = max(t0, t1) * (1.0f + 2.0f * gammaBound(3.0f));
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0f));
    float leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
    return enter <= leave ? enter : -1.0f;
}
#endif

RL_NAMESPACE_END
#endif
