// Next-event estimation towards an emissive triangle: a direction uniform over the solid angle it
// subtends where that is well conditioned, a point uniform over its area elsewhere, and the density
// of either per unit solid angle. Shared by C++ and GLSL.
#ifndef RAYLAB_TRIANGLE_LIGHT_GLSL
#define RAYLAB_TRIANGLE_LIGHT_GLSL
#include "compat.glsl"
#include "estimator_stages.glsl"
RL_NAMESPACE_BEGIN

// A point uniform over the triangle's area from u in [0, 1)²: barycentrics
// (1 − √u1, √u1·(1 − u2), √u1·u2) (Osada et al. 2002, "Shape Distributions", §4.2).
RL_FN vec3 sampleTrianglePoint(vec3 p0, vec3 p1, vec3 p2, vec2 u) {
    float s = sqrt(u.x);
    return p0 + (s * (1.0f - u.y)) * (p1 - p0) + (s * u.y) * (p2 - p0);
}

// The area density 1/A as a density per unit solid angle at the shading point: dω = |cosθl|·dA / r²
// (Veach 1997, eq. 8.10; pbrt-v4 §4.2.3), θl between the light's normal and the direction, r the
// distance. Two-sided, so |cosθl|. 0 when the triangle is seen edge-on or has no area.
RL_FN float triangleLightPdf(float dist2, float cosLight, float area) {
    float denom = abs(cosLight) * area;
    return denom > 0.0f ? dist2 / denom : 0.0f;
}

// Solid angles (sr) between which a triangle light is sampled by solid angle. Below the first, area
// sampling is as good, and float no longer holds Arvo's map to the triangle (a thin one at 2·10⁻⁴
// sr fails the χ² test that tests/shaders/triangle_light_test.cpp passes at 10⁻³ sr; pbrt-v4 goes
// down to 3·10⁻⁴);
// above the second the triangle fills nearly a hemisphere, where the map degenerates (pbrt-v4's
// Triangle::Sample, §6.5.4).
const float SPHERICAL_TRIANGLE_MIN_SOLID_ANGLE = 1e-3f;
const float SPHERICAL_TRIANGLE_MAX_SOLID_ANGLE = 6.22f;

// The solid angle of the spherical triangle of unit vectors a, b, c:
// tan(Ω/2) = |a·(b×c)| / (1 + a·b + b·c + c·a) (Van Oosterom & Strackee 1983).
RL_FN float sphericalTriangleArea(vec3 a, vec3 b, vec3 c) {
    return abs(2.0f * atan(abs(dot(a, cross(b, c))), 1.0f + dot(a, b) + dot(b, c) + dot(c, a)));
}

// A direction uniform over the spherical triangle of unit vectors a, b, c (the vertices of a
// triangle with edges e1 = p1 − p0, e2 = p2 − p0, seen from a point) of solid angle `area` (Arvo
// 1995, "Stratified Sampling of Spherical Triangles", §2): u.x picks the sub-triangle a, b, c' of
// area x = u.x·Ω with c' on the arc ac, u.y a point on the arc from b to c' by the cosine of its
// distance to b. Written for float and for llvmpipe, where every transcendental is a polynomial:
// the angle α at a enters only by its sine and cosine, from the great circles' normals, which come
// from the edges rather than from differences of nearby unit vectors; with φ = x − α, Arvo's
// cos φ − cos α and cos φ·cos α − 1 are products of half-angle sines; one sine and cosine, of x/2.
RL_FN vec3 sampleSphericalTriangle(vec3 a, vec3 b, vec3 c, vec3 e1, vec3 e2, float area, vec2 u) {
    vec3 n1 = normalize(cross(a, e1)), n2 = normalize(cross(a, e2));   // a × b ∥ a × e1, a × c ∥ a × e2
    float cosAlpha = dot(n1, n2), sinAlpha = length(cross(n1, n2));
    float h = sin(0.5f * u.x * area), hc = cos(0.5f * u.x * area);       // of x/2
    float sinX = 2.0f * h * hc, cosX = 1.0f - 2.0f * h * h;
    float s = sinX * cosAlpha - cosX * sinAlpha, t = cosX * cosAlpha + sinX * sinAlpha;   // of φ
    float g = sinAlpha * hc - cosAlpha * h;          // sin(α − x/2)
    float uu = 2.0f * h * g;                         // cos φ − cos α
    float v = s + sinAlpha * dot(a, b);              // dot(a, b): the cosine of the side opposite c
    float q = (-v * (g * g + h * h) - uu * s * cosAlpha) / ((v * s + uu * t) * sinAlpha);   // cos of arc a c'
    q = q >= dot(a, c) ? min(q, 1.0f) : dot(a, c);   // c' on the arc from a to c (rounding, or NaN)
    vec3 cPrime = normalize(q * a + sqrt(max(0.0f, 1.0f - q * q)) * normalize(e2 - dot(e2, a) * a));
    // On the arc from b to c' (length Θ), 1 − cos θ = u.y·(1 − cos Θ), i.e. sin(θ/2) = √u.y·sin(Θ/2);
    // the point as the slerp of b and c', which lands on c' at u.y = 1 where 1 − z² would not.
    float sinHalfArc = 0.5f * length(cPrime - b), cosHalfArc = 0.5f * length(cPrime + b);
    float sinArc = 2.0f * sinHalfArc * cosHalfArc, cosArc = 1.0f - 2.0f * sinHalfArc * sinHalfArc;
    float sh = min(1.0f, sqrt(u.y) * sinHalfArc);
    float ch = sqrt(max(0.0f, (1.0f - sh) * (1.0f + sh)));
    float sinTheta = 2.0f * sh * ch, cosTheta = 1.0f - 2.0f * sh * sh;
    float sinRest = sinArc * cosTheta - cosArc * sinTheta;   // sin(Θ − θ)
    return sinArc > 0.0f ? normalize(sinRest * b + sinTheta * cPrime) : b;
}

// The solid angle triangle (p0, p1, p2) subtends from p; 0 when a vertex is at p.
RL_FN float triangleSolidAngle(vec3 p, vec3 p0, vec3 p1, vec3 p2) {
    vec3 a = p0 - p, b = p1 - p, c = p2 - p;
    float la = length(a), lb = length(b), lc = length(c);
    if (!(la > 0.0f && lb > 0.0f && lc > 0.0f)) return 0.0f;
    return sphericalTriangleArea(a / la, b / lb, c / lc);
}

// Whether a triangle of solid angle Ω from the shading point is sampled by solid angle: never with
// render.light_sampling area, whose variant then holds none of that code.
RL_FN bool triangleLightBySolidAngle(float solidAngle) {
#if RAYLAB_LIGHT_SAMPLING == RAYLAB_LIGHT_SAMPLING_AREA
    return false;
#else
    return solidAngle >= SPHERICAL_TRIANGLE_MIN_SOLID_ANGLE && solidAngle <= SPHERICAL_TRIANGLE_MAX_SOLID_ANGLE;
#endif
}

// Density per unit solid angle with which sampleTriangleLight draws a direction from p that meets
// the triangle at squared distance dist2 with cosine cosLight to its normal.
RL_FN float triangleLightDirectionPdf(vec3 p, vec3 p0, vec3 p1, vec3 p2, float area, float dist2, float cosLight) {
    float solidAngle = triangleSolidAngle(p, p0, p1, p2);
    return triangleLightBySolidAngle(solidAngle) ? 1.0f / solidAngle : triangleLightPdf(dist2, cosLight, area);
}

// A direction from p towards the triangle light (p0, p1, p2) of the given area: by solid angle
// where triangleLightBySolidAngle holds, else through a point uniform over its area. Sets the unit
// direction and the point it meets; returns its solid-angle density (0: no direction).
RL_FN float sampleTriangleLight(vec3 p, vec3 p0, vec3 p1, vec3 p2, float area, vec2 u, RL_OUT(vec3) wi,
                                RL_OUT(vec3) point) {
    vec3 e1 = p1 - p0, e2 = p2 - p0, n = cross(e1, e2);
    vec3 a = p0 - p, b = p1 - p, c = p2 - p;
    float la = length(a), lb = length(b), lc = length(c);
    float solidAngle = la > 0.0f && lb > 0.0f && lc > 0.0f ? sphericalTriangleArea(a / la, b / lb, c / lc) : 0.0f;
    if (triangleLightBySolidAngle(solidAngle)) {
        wi = sampleSphericalTriangle(a / la, b / lb, c / lc, e1, e2, solidAngle, u);
        float t = dot(n, a) / dot(n, wi);   // where the direction meets the triangle's plane
        point = p + t * wi;
        return t > 0.0f ? 1.0f / solidAngle : 0.0f;
    }
    point = sampleTrianglePoint(p0, p1, p2, u);
    vec3 d = point - p;
    float dist2 = dot(d, d);
    wi = dist2 > 0.0f ? d / sqrt(dist2) : vec3(0.0f, 0.0f, 1.0f);
    return dist2 > 0.0f ? triangleLightPdf(dist2, dot(normalize(n), wi), area) : 0.0f;
}

RL_NAMESPACE_END
#endif
