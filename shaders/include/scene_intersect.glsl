// Nearest hit of a ray against the scene's geometry. GLSL only.
#ifndef RAYLAB_SCENE_INTERSECT_GLSL
#define RAYLAB_SCENE_INTERSECT_GLSL
#include "compat.glsl"
#include "ray.glsl"
#include "sphere.glsl"
#include "scene_data.glsl"

struct Hit {
    float t;
    vec3 position;   // on the surface
    vec3 normal;     // geometric, unit, pointing out of the object
    vec3 error;      // bound on the position's rounding error, per coordinate
    uint material;
};

bool intersectScene(Ray ray, out Hit hit) {
    hit.t = FLOAT_MAX;
    int nearest = -1;
    for (int i = 0; i < uSphereCount; ++i) {
        vec4 s = spheres[i].centerRadius;
        float t = intersectSphere(ray, s.xyz, s.w, 0.0f, hit.t);
        if (t > 0.0f) {
            hit.t = t;
            nearest = i;
        }
    }
    if (nearest < 0) return false;
    vec4 s = spheres[nearest].centerRadius;
    hit.position = sphereSurfacePoint(rayAt(ray, hit.t), s.xyz, s.w);
    hit.normal = normalize(hit.position - s.xyz);
    hit.error = sphereHitError(s.xyz, s.w);
    hit.material = spheres[nearest].info.x;
    return true;
}

// Any-hit query for shadow rays: is there geometry along the ray strictly before tMax?
bool occludedScene(Ray ray, float tMax) {
    for (int i = 0; i < uSphereCount; ++i) {
        vec4 s = spheres[i].centerRadius;
        if (intersectSphere(ray, s.xyz, s.w, 0.0f, tMax) > 0.0f) return true;
    }
    return false;
}

#endif
