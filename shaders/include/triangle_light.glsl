// Next-event estimation towards an emissive triangle: a point uniform over its area, and the
// density of the direction to that point per unit solid angle. Shared by C++ and GLSL.
#ifndef RAYLAB_TRIANGLE_LIGHT_GLSL
#define RAYLAB_TRIANGLE_LIGHT_GLSL
#include "compat.glsl"
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

RL_NAMESPACE_END
#endif
