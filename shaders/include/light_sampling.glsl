// Direction sampling towards lights, and the weights that combine it with BSDF sampling.
// Shared by C++ and GLSL.
#ifndef RAYLAB_LIGHT_SAMPLING_GLSL
#define RAYLAB_LIGHT_SAMPLING_GLSL
#include "compat.glsl"
#include "frame.glsl"
RL_NAMESPACE_BEGIN

// Below sin²θmax of about (1.5°)² the cosine of the cone is computed from sin² by a Taylor
// expansion, because 1 − cosθmax cancels in float (pbrt-v4 Sphere::Sample, §6.2.4).
const float SMALL_CONE_SIN2 = 0.00068523f;

// 1 − cosθmax of the cone a sphere subtends from p; 0 when p is inside or on the sphere (no cone).
RL_FN float sphereConeOneMinusCos(vec3 p, vec3 center, float radius) {
    vec3 d = center - p;
    float dist2 = dot(d, d);
    float r2 = radius * radius;
    if (dist2 <= r2 * 1.0001f) return 0.0f;
    float sin2Max = r2 / dist2;
    if (sin2Max < SMALL_CONE_SIN2) return 0.5f * sin2Max;
    return 1.0f - sqrt(max(0.0f, 1.0f - sin2Max));
}

// Solid-angle density of sphereConeSample for a direction inside the cone (0 without a cone).
RL_FN float sphereConePdf(vec3 p, vec3 center, float radius) {
    float oneMinusCos = sphereConeOneMinusCos(p, center, radius);
    return oneMinusCos > 0.0f ? 1.0f / (2.0f * PI * oneMinusCos) : 0.0f;
}

// A direction uniform over the cone of directions from p that the sphere subtends (pbrt-v4
// Sphere::Sample by solid angle). Returns the unit direction; pdf via sphereConePdf.
RL_FN vec3 sphereConeSample(vec3 p, vec3 center, float radius, vec2 u) {
    vec3 d = center - p;
    float dist2 = dot(d, d);
    float sin2Max = radius * radius / dist2;
    float oneMinusCos = sphereConeOneMinusCos(p, center, radius);
    float cosTheta = 1.0f - u.x * oneMinusCos;
    float sin2Theta = max(0.0f, 1.0f - cosTheta * cosTheta);
    if (sin2Max < SMALL_CONE_SIN2) {
        sin2Theta = sin2Max * u.x;   // (1 − cos) ≈ sin²/2 to first order
        cosTheta = sqrt(1.0f - sin2Theta);
    }
    float sinTheta = sqrt(sin2Theta);
    float phi = 2.0f * PI * u.y;
    Frame f = frameFromNormal(d / sqrt(dist2));
    return normalize(frameToWorld(f, vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta)));
}

// Uniform over the sphere of directions (for the sky): pdf 1/(4π).
RL_FN vec3 sampleUniformSphere(vec2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = sqrt(max(0.0f, 1.0f - z * z));
    float phi = 2.0f * PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}
const float UNIFORM_SPHERE_PDF = 0.0795774715459477f;   // 1/(4π)

// Veach's power heuristic with β = 2 (Veach 1997, §9.2.4): weight of the strategy with density a
// when the other one has density b.
RL_FN float powerHeuristic(float a, float b) {
    if (!(a > 0.0f)) return 0.0f;
    if (!(b > 0.0f)) return 1.0f;
    // Written as 1/(1 + (b/a)²) so that huge densities cannot overflow the squares.
    float r = b / a;
    return 1.0f / (1.0f + r * r);
}

RL_NAMESPACE_END
#endif
