// Ray–sphere intersection in the precision-improved form of Haines, Günther & Akenine-Möller,
// "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7, 2019.
#ifndef RAYLAB_SPHERE_GLSL
#define RAYLAB_SPHERE_GLSL
#include "compat.glsl"
#include "ray.glsl"
RL_NAMESPACE_BEGIN

// Nearest t in (tMin, tMax) where the ray meets the sphere, or -1 for a miss.
#ifdef RAYLAB_EXERCISE_RAY_SPHERE
#include RAYLAB_EXERCISE_RAY_SPHERE   // a pupil's intersectSphere (exercises/README.md)
#else
RL_FN float intersectSphere(Ray ray, vec3 center, float radius, float tMin, float tMax) {
    vec3 f = ray.origin - center;
    float a = dot(ray.dir, ray.dir);
    float bPrime = -dot(f, ray.dir);
    // r² − |f + (b'/a)·d|²: the squared distance from the centre to the line, taken from r²,
    // avoids the cancellation of the textbook b'² − a·c when the sphere is small or far away.
    vec3 l = f + (bPrime / a) * ray.dir;
    float discriminant = radius * radius - dot(l, l);
    if (discriminant < 0.0f) return -1.0f;
    float c = dot(f, f) - radius * radius;
    float root = sqrt(a * discriminant);
    float q = bPrime >= 0.0f ? bPrime + root : bPrime - root;
    // Both roots without subtracting nearly equal numbers: t0·t1 = c/a.
    float t0 = c / q;
    float t1 = q / a;
    float tNear = min(t0, t1);
    float tFar = max(t0, t1);
    if (tNear > tMin && tNear < tMax) return tNear;
    if (tFar > tMin && tFar < tMax) return tFar;
    return -1.0f;
}
#endif

// The hit point re-projected onto the surface (the t-based point carries the error of t).
RL_FN vec3 sphereSurfacePoint(vec3 p, vec3 center, float radius) {
    return center + radius * normalize(p - center);
}

// Per-coordinate bound on the error of sphereSurfacePoint, after pbrt-v4 Sphere: γ(5)·|p − c|
// for the re-projection, plus the rounding of adding the centre back, γ(3)·(|c| + r). Doubled
// for safety: it also covers the rounding of the origin − centre difference in intersectSphere,
// which is what makes a radius-1000 ground sphere at y = −1000 self-intersect with small offsets.
RL_FN vec3 sphereHitError(vec3 center, float radius) {
    return 2.0f * (gammaBound(5.0f) * vec3(radius) + gammaBound(3.0f) * (abs(center) + vec3(radius)));
}

RL_NAMESPACE_END
#endif
