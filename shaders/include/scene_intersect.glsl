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
    uint escapes;         // the object's INSTANCE_ESCAPES_* bits (accel/escape_sides.h)
};

// The search render.accel chose. `leaving` (traceScene): the instance the ray leaves outwards, or
// NO_INSTANCE; every search leaves it out, so all three find the same hits.
bool traceSceneAccel(Ray ray, float tMax, bool anyHit, uint leaving, out TraceRecord rec) {
#if RAYLAB_ACCEL == RAYLAB_ACCEL_BOXES
    return traceSceneFlat(ray, tMax, anyHit, true, leaving, rec);
#elif RAYLAB_ACCEL == RAYLAB_ACCEL_NONE
    return traceSceneFlat(ray, tMax, anyHit, false, leaving, rec);
#else
    return traceScene(ray, tMax, anyHit, leaving, rec);
#endif
}

// Rays closer than this cosine to the plane of the face they leave search that object too: the
// side of a grazing direction is not worth trusting to float (about 0.06°; a cosine-distributed
// direction is that close with probability 1e-6).
const float ESCAPE_MIN_COSINE = 1e-3f;

// Tests compile the tracer with 0 to search every object (tests/render/accel_render_test.cpp).
#ifndef RAYLAB_LEAVE_OUT_ESCAPED
#define RAYLAB_LEAVE_OUT_ESCAPED 1
#endif

// The instance a ray leaving the hit along unit dir cannot meet again (accel/escape_sides.h), to
// leave out of its search; NO_INSTANCE when it might.
uint leavingInstance(Hit hit, vec3 dir) {
    float c = dot(dir, hit.normal);
    uint side = c > ESCAPE_MIN_COSINE ? INSTANCE_ESCAPES_FRONT : (c < -ESCAPE_MIN_COSINE ? INSTANCE_ESCAPES_BACK : 0u);
    return RAYLAB_LEAVE_OUT_ESCAPED != 0 && (hit.escapes & side) != 0u ? hit.instance : NO_INSTANCE;
}

bool intersectScene(Ray ray, uint leaving, out Hit hit) {
    TraceRecord rec;
    if (!traceSceneAccel(ray, FLOAT_MAX, false, leaving, rec)) return false;
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
    hit.escapes = s.escapes;
    return true;
}

bool intersectScene(Ray ray, out Hit hit) { return intersectScene(ray, NO_INSTANCE, hit); }

// Shadow rays: is there any surface in (0, tMax) along the ray (t in units of |ray.dir|)?
bool occluded(Ray ray, float tMax, uint leaving) {
    TraceRecord rec;
    return traceSceneAccel(ray, tMax, true, leaving, rec);
}

bool occluded(Ray ray, float tMax) { return occluded(ray, tMax, NO_INSTANCE); }

#endif
