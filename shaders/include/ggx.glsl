// The Trowbridge–Reitz (GGX) microfacet distribution, isotropic, in the local frame (+z normal):
// D, Smith masking with the height-correlated G2, and sampling of visible normals or of D·cos.
// Shared by C++ and GLSL.
#ifndef RAYLAB_GGX_GLSL
#define RAYLAB_GGX_GLSL
#include "compat.glsl"
#include "estimator_stages.glsl"
RL_NAMESPACE_BEGIN

// α is clamped from below (pbrt-v4 TrowbridgeReitzDistribution); below GGX_DELTA_ALPHA the lobe
// is so narrow that it is treated as a perfect mirror (a delta lobe, never evaluated).
const float GGX_MIN_ALPHA = 1e-4f;
const float GGX_DELTA_ALPHA = 1e-3f;

RL_FN float ggxAlpha(float perceptualRoughness) {
    return max(perceptualRoughness * perceptualRoughness, GGX_MIN_ALPHA);
}
RL_FN bool ggxIsDelta(float alpha) { return alpha < GGX_DELTA_ALPHA; }

// D(h) = 1 / (π α² cos⁴θ (1 + tan²θ/α²)²) (Walter et al. 2007, eq. 33); 0 where cos⁴θ underflows.
#ifdef RAYLAB_EXERCISE_GGX_D
#include RAYLAB_EXERCISE_GGX_D   // a pupil's ggxD (exercises/README.md)
#else
RL_FN float ggxD(vec3 h, float alpha) {
    float cos2 = h.z * h.z;
    float cos4 = cos2 * cos2;
    if (cos4 < 1e-16f) return 0.0f;
    float a2 = alpha * alpha;
    float e = (h.x * h.x + h.y * h.y) / (cos2 * a2);
    return 1.0f / (PI * a2 * cos4 * (1.0f + e) * (1.0f + e));
}
#endif

#ifdef RAYLAB_EXERCISE_SMITH_G
#include RAYLAB_EXERCISE_SMITH_G   // a pupil's ggxG1 (exercises/README.md)

// Height-correlated G2 from the pupil's G1 through Λ = 1/G1 − 1 (Heitz 2014, eq. 99).
RL_FN float ggxG2(vec3 wo, vec3 wi, float alpha) {
    return 1.0f / (1.0f / ggxG1(wo, alpha) + 1.0f / ggxG1(wi, alpha) - 1.0f);
}
#else
// Smith Λ for GGX: (√(1 + α² tan²θ) − 1)/2 (Heitz 2014, "Understanding the Masking-Shadowing
// Function", eq. 72), written as x / (2(√(1 + x) + 1)) to avoid cancellation for small x.
RL_FN float ggxLambda(vec3 w, float alpha) {
    float cos2 = w.z * w.z;
    if (cos2 < 1e-20f) return 1e20f;   // grazing: fully masked
    float x = alpha * alpha * (w.x * w.x + w.y * w.y) / cos2;
    return x / (2.0f * (sqrt(1.0f + x) + 1.0f));
}

RL_FN float ggxG1(vec3 w, float alpha) { return 1.0f / (1.0f + ggxLambda(w, alpha)); }

// Height-correlated masking-shadowing (Heitz 2014, eq. 99).
RL_FN float ggxG2(vec3 wo, vec3 wi, float alpha) {
    return 1.0f / (1.0f + ggxLambda(wo, alpha) + ggxLambda(wi, alpha));
}
#endif

// Visible-normal sampling by spherical caps (Dupuy & Benyoub 2023, "Sampling Visible GGX Normals
// with Spherical Caps", listing 3; same distribution as Heitz 2018, JCGT 7(4)). wo.z > 0.
RL_FN vec3 ggxSampleVisibleNormal(vec3 wo, float alpha, vec2 u) {
    vec3 wh = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));   // to the hemisphere config
    float phi = 2.0f * PI * u.x;
    float z = (1.0f - u.y) * (1.0f + wh.z) - wh.z;
    float sinTheta = sqrt(clamp(1.0f - z * z, 0.0f, 1.0f));
    vec3 c = vec3(sinTheta * cos(phi), sinTheta * sin(phi), z);
    vec3 hs = c + wh;                                                // hs.z = (1 − u.y)(1 + wh.z) > 0
    return normalize(vec3(alpha * hs.x, alpha * hs.y, hs.z));
}

// Density of ggxSampleVisibleNormal over h: D_wo(h) = G1(wo) max(0, wo·h) D(h) / cosθo
// (Heitz 2018, eq. 3).
RL_FN float ggxVisibleNormalPdf(vec3 wo, vec3 h, float alpha) {
    if (wo.z <= 0.0f) return 0.0f;
    return ggxG1(wo, alpha) * max(0.0f, dot(wo, h)) * ggxD(h, alpha) / wo.z;
}

// The classic alternative (render.ggx_sampling d_cos; bench/estimator_stages.md): h drawn with
// density D(h) cosθh (Walter et al. 2007, eq. 35–36), blind to wo, so its weights blow up at grazing wo.
RL_FN vec3 ggxSampleDCos(float alpha, vec2 u) {
    float tan2 = alpha * alpha * u.x / max(1.0f - u.x, 1e-12f);
    float cosTheta = 1.0f / sqrt(1.0f + tan2);
    float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * PI * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}
RL_FN float ggxDCosPdf(vec3 h, float alpha) { return ggxD(h, alpha) * max(h.z, 0.0f); }

// The normal render.ggx_sampling draws (method: RAYLAB_GGX_VNDF or RAYLAB_GGX_D_COS), h.z > 0, and
// its density over h. D·cos also draws normals facing away from wo; callers drop those.
RL_FN vec3 ggxSampleNormal(int method, vec3 wo, float alpha, vec2 u) {
    return method == RAYLAB_GGX_D_COS ? ggxSampleDCos(alpha, u) : ggxSampleVisibleNormal(wo, alpha, u);
}
RL_FN float ggxNormalPdf(int method, vec3 wo, vec3 h, float alpha) {
    return method == RAYLAB_GGX_D_COS ? ggxDCosPdf(h, alpha) : ggxVisibleNormalPdf(wo, h, alpha);
}

RL_NAMESPACE_END
#endif
