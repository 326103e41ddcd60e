// Nearest hit of a ray against the scene's geometry, and shadow-ray occlusion, through the
// two-level BVH (bvh_traversal.glsl) or, by render.accel, without it (flat_traversal.glsl).
// GLSL only.
#ifndef RAYLAB_SCENE_INTERSECT_GLSL
#define RAYLAB_SCENE_INTERSECT_GLSL
#include "compat.glsl"
#include "ray.glsl"
#include "scene_data.glsl"
#include "scene_geometry.glsl"
#include "bvh_traversal.glsl"
#include "estimator_stages.glsl"
#if RAYLAB_ACCEL != RAYLAB_ACCEL_BVH
#include "flat_traversal.glsl"
#endif

struct Hit {
    float t;
    vec3 position;        // on the surface
    vec3 normal;          // geometric, unit, pointing out of the object (sphere) / e01 × e02 side
    vec3 error;           // bound on the position's rounding error, per coordinate
    uint material;
    vec3 shadingNormal;   // interpolated vertex normal (smooth shading); = normal without one
    vec2 uv;
    float lodBase;        // ½·log2(uv area / world area), for texture LOD (texture.glsl)
    vec3 tangent;         // ∂p/∂u, world space (normal maps)
    uint instance;        // index into instances[]
    uint primitive;       // sphere index, or global triangle index
};

// The search render.accel chose.
bool traceSceneAccel(Ray ray, float tMax, bool anyHit, out TraceRecord rec) {
#if RAYLAB_ACCEL == RAYLAB_ACCEL_BOXES
    return traceSceneFlat(ray, tMax, anyHit, true, rec);
#elif RAYLAB_ACCEL == RAYLAB_ACCEL_NONE
    return traceSceneFlat(ray, tMax, anyHit, false, rec);
#else
    return traceScene(ray, tMax, anyHit, rec);
#endif
}

bool intersectScene(Ray ray, out Hit hit) {
    TraceRecord rec;
    if (!traceSceneAccel(ray, FLOAT_MAX, false, rec)) return false;
    SurfaceHit s = surfaceAt(ray, rec);
    hit.t = rec.t;
    hit.position = s.position;
    hit.normal = s.normal;
    hit.error = s.error;
    hit.material = s.material;
    hit.shadingNormal = s.shadingNormal;
    hit.uv = s.uv;
    hit.lodBase = s.lodBase;
    hit.tangent = s.tangent;
    hit.instance = rec.instance;
    hit.primitive = rec.primitive;
    return true;
}

// Shadow rays: is there any surface in (0, tMax) along the ray (t in units of |ray.dir|)?
bool occluded(Ray ray, float tMax) {
    TraceRecord rec;
    return traceSceneAccel(ray, tMax, true, rec);
}

#endif
