// Fresnel reflectance: Schlick's approximation for the specular layer, the exact unpolarised form
// for dielectric interfaces. Shared by C++ and GLSL.
#ifndef RAYLAB_FRESNEL_GLSL
#define RAYLAB_FRESNEL_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

// Schlick 1994 with a grazing value f90: F = f0 + (f90 − f0)(1 − cosθ)⁵.
#ifdef RAYLAB_EXERCISE_SCHLICK
#include RAYLAB_EXERCISE_SCHLICK   // a pupil's schlickFresnel(f0, f90, wo, wi) (exercises/README.md)

// The pair of directions mirrored about the normal whose halfway vector is +z at angle θ.
RL_FN vec3 fresnelSchlick(vec3 f0, float f90, float cosTheta) {
    float c = clamp(cosTheta, 0.0f, 1.0f);
    float s = sqrt(1.0f - c * c);
    return schlickFresnel(f0, f90, vec3(s, 0.0f, c), vec3(-s, 0.0f, c));
}
#else
RL_FN vec3 fresnelSchlick(vec3 f0, float f90, float cosTheta) {
    float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (vec3(f90) - f0) * (m2 * m2 * m);
}
#endif

// Grazing reflectance for a given f0: min(1, 50·max(f0)) (Filament, "Physically Based Rendering
// in Filament", §4.8.3 / specular occlusion). f0 = 0 then means no specular reflection at all.
RL_FN float schlickF90(vec3 f0) { return min(1.0f, 50.0f * max(f0.x, max(f0.y, f0.z))); }

// Exact Fresnel reflectance of a smooth dielectric interface for unpolarised light (pbrt-v4
// FrDielectric, §9.3.3). cosI = |cos| of the incident angle, eta = n_transmitted / n_incident.
// Total internal reflection and exact grazing incidence give 1.
RL_FN float fresnelDielectric(float cosI, float eta) {
    cosI = clamp(cosI, 0.0f, 1.0f);
    float sin2T = (1.0f - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0f || cosI <= 0.0f) return 1.0f;
    float cosT = sqrt(max(0.0f, 1.0f - sin2T));
    float rParallel = (eta * cosI - cosT) / (eta * cosI + cosT);
    float rPerpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5f * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

RL_NAMESPACE_END
#endif
