// A smooth dielectric interface (glass): Fresnel-weighted choice between mirror reflection and
// Snell refraction, total internal reflection included. Shared by C++ and GLSL.
#ifndef RAYLAB_DIELECTRIC_GLSL
#define RAYLAB_DIELECTRIC_GLSL
#include "compat.glsl"
#include "fresnel.glsl"
#include "bsdf_sample.glsl"
RL_NAMESPACE_BEGIN

// Local frame: +z is the outward normal. wo.z > 0: wo is outside and the ray enters a medium of
// relative index ior; wo.z < 0: wo is inside and the ray leaves it (relative index 1/ior).
// Reflection with probability F, refraction with 1 − F, so the weight is 1 for reflection and
// 1/η² for refraction: radiance is compressed into the smaller solid angle on entering
// (pbrt-v4 DielectricBxDF::Sample_f, radiance mode, §9.5.2). A round trip in and out is 1.
RL_FN BsdfSample dielectricSample(vec3 wo, float ior, float u) {
    bool entering = wo.z > 0.0f;
    float eta = entering ? ior : 1.0f / ior;
    float cosI = abs(wo.z);
    float F = fresnelDielectric(cosI, eta);
    if (u < F) {
        return BsdfSample(vec3(-wo.x, -wo.y, wo.z), vec3(1.0f), F, LOBE_GLASS_REFLECT, true);
    }
    float sin2T = (1.0f - cosI * cosI) / (eta * eta);
    float cosT = sqrt(max(0.0f, 1.0f - sin2T));
    float side = entering ? 1.0f : -1.0f;   // the normal on wo's side
    vec3 wi = -wo / eta + vec3(0.0f, 0.0f, side * (cosI / eta - cosT));
    wi = normalize(wi);
    return BsdfSample(wi, vec3(1.0f / (eta * eta)), 1.0f - F, LOBE_GLASS_TRANSMIT, true);
}

RL_NAMESPACE_END
#endif
