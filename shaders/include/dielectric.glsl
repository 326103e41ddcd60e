// A smooth dielectric interface (glass): Fresnel-weighted choice between mirror reflection and
// Snell refraction, total internal reflection included. Shared by C++ and GLSL.
#ifndef RAYLAB_DIELECTRIC_GLSL
#define RAYLAB_DIELECTRIC_GLSL
#include "compat.glsl"
#include "fresnel.glsl"
#include "bsdf_sample.glsl"
#include "ggx.glsl"
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

// ---- Rough dielectric: Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces", with visible-normal sampling (as in pbrt-v4 DielectricBxDF). Same frame conventions
// as above; all three functions work in a frame mirrored so that wo.z > 0, and η is the index
// of the side wi refracts into over the side of wo.

RL_FN float dielectricEta(vec3 wo, float ior) { return wo.z > 0.0f ? ior : 1.0f / ior; }

// Generalised half vector of a pair (Walter eq. 16), oriented to +z, with the factor
// |wi·h| / (wi·h + wo·h/η)², the Jacobian dωh/dωi of refraction (Walter eq. 17). Returns false
// for pairs no microfacet connects (back-facing microfacets, Walter §5.1).
RL_FN bool roughDielectricHalf(vec3 wo, vec3 wi, float eta, RL_OUT(vec3) h, RL_OUT(float) jacobian) {
    bool reflect = wi.z > 0.0f;
    float etap = reflect ? 1.0f : eta;
    vec3 hRaw = wi * etap + wo;
    h = vec3(0.0f, 0.0f, 1.0f);
    jacobian = 0.0f;
    if (wi.z == 0.0f || dot(hRaw, hRaw) == 0.0f) return false;
    h = normalize(hRaw);
    if (h.z < 0.0f) h = -h;
    if (dot(h, wi) * wi.z < 0.0f || dot(h, wo) * wo.z < 0.0f) return false;
    if (reflect) {
        jacobian = 1.0f / (4.0f * abs(dot(wo, h)));
    } else {
        float d = dot(wi, h) + dot(wo, h) / eta;
        if (d == 0.0f) return false;
        jacobian = abs(dot(wi, h)) / (d * d);
    }
    return true;
}

// f·|cosθi| (radiance: refraction scaled by 1/η², pbrt-v4 §9.7.2). wo.z > 0.
RL_FN float roughDielectricEvalUp(vec3 wo, vec3 wi, float alpha, float eta) {
    vec3 h;
    float jacobian;
    if (!roughDielectricHalf(wo, wi, eta, h, jacobian)) return 0.0f;
    float F = fresnelDielectric(dot(wo, h), eta);
    float DG = ggxD(h, alpha) * ggxG2(wo, wi, alpha);
    if (wi.z > 0.0f) return DG * F / (4.0f * wo.z);
    // D G2 (1 − F) |wi·h| |wo·h| / (|cosθi| cosθo (wi·h + wo·h/η)²) · |cosθi| / η²
    return DG * (1.0f - F) * jacobian * abs(dot(wo, h)) / (wo.z * eta * eta);
}

RL_FN float roughDielectricPdfUp(vec3 wo, vec3 wi, float alpha, float eta, int ggxSampling) {
    vec3 h;
    float jacobian;
    if (!roughDielectricHalf(wo, wi, eta, h, jacobian)) return 0.0f;
    float F = fresnelDielectric(dot(wo, h), eta);
    float choice = wi.z > 0.0f ? F : 1.0f - F;
    return choice * ggxNormalPdf(ggxSampling, wo, h, alpha) * jacobian;
}

RL_FN float roughDielectricEval(vec3 wo, vec3 wi, float alpha, float ior) {
    float s = wo.z < 0.0f ? -1.0f : 1.0f;
    return roughDielectricEvalUp(vec3(wo.x, wo.y, s * wo.z), vec3(wi.x, wi.y, s * wi.z), alpha,
                                 dielectricEta(wo, ior));
}

RL_FN float roughDielectricPdf(vec3 wo, vec3 wi, float alpha, float ior, int ggxSampling) {
    float s = wo.z < 0.0f ? -1.0f : 1.0f;
    return roughDielectricPdfUp(vec3(wo.x, wo.y, s * wo.z), vec3(wi.x, wi.y, s * wi.z), alpha,
                                dielectricEta(wo, ior), ggxSampling);
}

// A microfacet normal h (render.ggx_sampling), then reflection with probability F(wo·h), else
// refraction through h. Returns the direction only (lobe set, weight and pdf left to the caller);
// LOBE_NONE when h faces away from wo or the direction ends on the wrong side.
RL_FN BsdfSample roughDielectricSample(vec3 wo, float alpha, float ior, int ggxSampling, vec2 u, float uChoice) {
    if (wo.z == 0.0f) return bsdfNoSample();
    float s = wo.z < 0.0f ? -1.0f : 1.0f;
    float eta = dielectricEta(wo, ior);
    vec3 woUp = vec3(wo.x, wo.y, s * wo.z);
    vec3 h = ggxSampleNormal(ggxSampling, woUp, alpha, u);
    float cosI = dot(woUp, h);
    if (cosI <= 0.0f) return bsdfNoSample();
    float F = fresnelDielectric(cosI, eta);
    vec3 wi;
    int lobe;
    if (uChoice < F) {
        wi = 2.0f * cosI * h - woUp;
        if (wi.z <= 0.0f) return bsdfNoSample();
        lobe = LOBE_GLASS_REFLECT;
    } else {
        float sin2T = (1.0f - cosI * cosI) / (eta * eta);
        if (sin2T >= 1.0f) return bsdfNoSample();
        float cosT = sqrt(1.0f - sin2T);
        wi = normalize(-woUp / eta + (cosI / eta - cosT) * h);
        if (wi.z >= 0.0f) return bsdfNoSample();
        lobe = LOBE_GLASS_TRANSMIT;
    }
    return BsdfSample(vec3(wi.x, wi.y, s * wi.z), vec3(0.0f), 0.0f, lobe, false);
}

RL_NAMESPACE_END
#endif
