// Affine transforms of points, directions and normals by the rows of a 3×4 matrix, with the
// rounding-error bound of a transformed point (pbrt-v4 Transform::operator()(Point3fi), §6.8.6).
// Shared by C++ and GLSL.
#ifndef RAYLAB_INSTANCE_TRANSFORM_GLSL
#define RAYLAB_INSTANCE_TRANSFORM_GLSL
#include "compat.glsl"
#include "ray.glsl"
RL_NAMESPACE_BEGIN

RL_FN vec3 xyzOf(vec4 v) { return vec3(v.x, v.y, v.z); }

RL_FN vec3 transformPoint(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
    return vec3(dot(xyzOf(r0), p) + r0.w, dot(xyzOf(r1), p) + r1.w, dot(xyzOf(r2), p) + r2.w);
}

RL_FN vec3 transformVector(vec4 r0, vec4 r1, vec4 r2, vec3 v) {
    return vec3(dot(xyzOf(r0), v), dot(xyzOf(r1), v), dot(xyzOf(r2), v));
}

// A normal goes by the inverse transpose: given the rows of the inverse, n' = Σ row_i · n_i.
RL_FN vec3 transformNormal(vec4 inv0, vec4 inv1, vec4 inv2, vec3 n) {
    return xyzOf(inv0) * n.x + xyzOf(inv1) * n.y + xyzOf(inv2) * n.z;
}

RL_FN float transformedErrorRow(vec4 r, vec3 p, vec3 e) {
    vec3 m = abs(xyzOf(r));
    return (gammaBound(3.0f) + 1.0f) * dot(m, e) + gammaBound(3.0f) * (dot(m, abs(p)) + abs(r.w));
}

// Error bound of transformPoint(p) when p itself is known within ±e per coordinate.
RL_FN vec3 transformPointError(vec4 r0, vec4 r1, vec4 r2, vec3 p, vec3 e) {
    return vec3(transformedErrorRow(r0, p, e), transformedErrorRow(r1, p, e), transformedErrorRow(r2, p, e));
}

RL_NAMESPACE_END
#endif
