// Watertight ray–triangle intersection (Woop, Benthin & Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013), with pbrt-v4's conservative t > 0 test and hit-point error
// bound (pbrt-v4 IntersectTriangle, §6.5.3 and §6.8.4). Shared by C++ and GLSL.
// A shared edge is evaluated by the very same 2D edge function from both of its triangles, so a
// ray through an edge or a vertex hits at least one of them: no cracks.
#ifndef RAYLAB_TRIANGLE_GLSL
#define RAYLAB_TRIANGLE_GLSL
#include "compat.glsl"
#include "ray.glsl"
RL_NAMESPACE_BEGIN

struct TriangleHit {
    float t;
    float b0;   // barycentric weights of p0, p1, p2
    float b1;
    float b2;
};

RL_FN int maxDimension(vec3 v) {
    return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}

RL_FN vec3 permuteAxes(vec3 v, int x, int y, int z) { return vec3(v[x], v[y], v[z]); }

// The per-ray part of the watertight test (Woop et al. 2013, §3): the axis permutation that makes z
// the ray's dominant axis and the shear that turns the ray into +z, computed once for all the
// triangles a ray meets instead of once per triangle.
struct TriangleRay {
    vec3 origin;
    ivec3 axes;   // kx, ky, kz
    vec3 shear;   // Sx, Sy, Sz
};

RL_FN TriangleRay triangleRay(Ray ray) {
    int kz = maxDimension(abs(ray.dir));
    int kx = kz + 1;
    if (kx == 3) kx = 0;
    int ky = kx + 1;
    if (ky == 3) ky = 0;
    vec3 d = permuteAxes(ray.dir, kx, ky, kz);
    return TriangleRay(ray.origin, ivec3(kx, ky, kz), vec3(-d.x / d.z, -d.y / d.z, 1.0f / d.z));
}

#ifdef RAYLAB_EXERCISE_RAY_TRIANGLE
#include RAYLAB_EXERCISE_RAY_TRIANGLE   // a pupil's intersectTriangle(Ray, ...) (exercises/README.md)

// The traversal's sheared ray handed to the pupil's function as origin and direction again.
RL_FN bool intersectTriangle(TriangleRay ray, vec3 p0, vec3 p1, vec3 p2, float tMax, RL_OUT(TriangleHit) hit) {
    vec3 d;
    d[ray.axes.z] = 1.0f / ray.shear.z;
    d[ray.axes.x] = -ray.shear.x * d[ray.axes.z];
    d[ray.axes.y] = -ray.shear.y * d[ray.axes.z];
    return intersectTriangle(Ray(ray.origin, d), p0, p1, p2, tMax, hit);
}
#else
// Hit in (0, tMax) of the ray and triangle p0 p1 p2, either side; false for degenerate triangles.
RL_FN bool intersectTriangle(TriangleRay ray, vec3 p0, vec3 p1, vec3 p2, float tMax, RL_OUT(TriangleHit) hit) {
    // Degenerate in float (collinear or coincident vertices, e.g. a tiny triangle far from the
    // origin whose vertices rounded together): never hit, and its normal would be NaN.
    vec3 area = cross(p2 - p0, p1 - p0);
    if (dot(area, area) == 0.0f) return false;
    // Vertices relative to the origin, axes permuted so that z is the ray's dominant axis.
    int kx = ray.axes.x;
    int ky = ray.axes.y;
    int kz = ray.axes.z;
    vec3 a = permuteAxes(p0 - ray.origin, kx, ky, kz);
    vec3 b = permuteAxes(p1 - ray.origin, kx, ky, kz);
    vec3 c = permuteAxes(p2 - ray.origin, kx, ky, kz);
    // Shear so the ray runs along +z; z is scaled only once an intersection is likely.
    float sx = ray.shear.x;
    float sy = ray.shear.y;
    float sz = ray.shear.z;
    a.x += sx * a.z;
    a.y += sy * a.z;
    b.x += sx * b.z;
    b.y += sy * b.z;
    c.x += sx * c.z;
    c.y += sy * c.z;
    // 2D edge functions; an exact zero is recomputed in double so the sign is right.
    float e0 = b.x * c.y - b.y * c.x;
    float e1 = c.x * a.y - c.y * a.x;
    float e2 = a.x * b.y - a.y * b.x;
    if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
        e0 = float(double(b.x) * double(c.y) - double(b.y) * double(c.x));
        e1 = float(double(c.x) * double(a.y) - double(c.y) * double(a.x));
        e2 = float(double(a.x) * double(b.y) - double(a.y) * double(b.x));
    }
    if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) return false;
    float det = e0 + e1 + e2;
    if (!(det < 0.0f) && !(det > 0.0f)) return false;   // 0, or NaN from a NaN ray
    // z in world units, for the error of the sheared x and y (|sx|, |sy| <= 1): the scaled z would
    // make the bound below grow as the direction shortens and reject real hits.
    float maxZ = max(max(abs(a.z), abs(b.z)), abs(c.z));
    // Scaled distance compared against tMax·det: no division before we know it is a hit.
    a.z *= sz;
    b.z *= sz;
    c.z *= sz;
    float tScaled = e0 * a.z + e1 * b.z + e2 * c.z;
    if (det < 0.0f && (tScaled >= 0.0f || tScaled < tMax * det)) return false;
    if (det > 0.0f && (tScaled <= 0.0f || tScaled > tMax * det)) return false;
    float invDet = 1.0f / det;
    float t = tScaled * invDet;
    // t must be provably > 0 given the rounding above (pbrt-v4 §6.8.7).
    float maxZt = max(max(abs(a.z), abs(b.z)), abs(c.z));
    float deltaZ = gammaBound(3.0f) * maxZt;
    float maxXt = max(max(abs(a.x), abs(b.x)), abs(c.x));
    float maxYt = max(max(abs(a.y), abs(b.y)), abs(c.y));
    float deltaX = gammaBound(5.0f) * (maxXt + maxZ);
    float deltaY = gammaBound(5.0f) * (maxYt + maxZ);
    float deltaE = 2.0f * (gammaBound(2.0f) * maxXt * maxYt + deltaY * maxXt + deltaX * maxYt);
    float maxE = max(max(abs(e0), abs(e1)), abs(e2));
    float deltaT = 3.0f * (gammaBound(3.0f) * maxE * maxZt + deltaE * maxZt + deltaZ * maxE) * abs(invDet);
    if (!(t > deltaT)) return false;
    hit = TriangleHit(t, e0 * invDet, e1 * invDet, e2 * invDet);
    return true;
}

RL_FN bool intersectTriangle(Ray ray, vec3 p0, vec3 p1, vec3 p2, float tMax, RL_OUT(TriangleHit) hit) {
    return intersectTriangle(triangleRay(ray), p0, p1, p2, tMax, hit);
}
#endif

// The hit point from barycentrics (its error does not grow with t, unlike o + t·d).
RL_FN vec3 triangleHitPoint(TriangleHit h, vec3 p0, vec3 p1, vec3 p2) {
    return h.b0 * p0 + h.b1 * p1 + h.b2 * p2;
}

// Per-coordinate bound on the rounding error of triangleHitPoint (pbrt-v4 §6.8.5: γ(7)).
RL_FN vec3 triangleHitError(TriangleHit h, vec3 p0, vec3 p1, vec3 p2) {
    return gammaBound(7.0f) * (abs(h.b0 * p0) + abs(h.b1 * p1) + abs(h.b2 * p2));
}

RL_NAMESPACE_END
#endif
