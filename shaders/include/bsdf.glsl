// The material's BSDF in the local frame (+z = the surface's outward normal): a Lambertian base
// under a GGX specular layer, mixed by `transmission` with a dielectric (glass) that is smooth
// (a delta lobe) below GGX_DELTA_ALPHA and rough (Walter et al. 2007) above. sample / eval /
// pdf agree: weight = eval / pdf for every non-delta sample. Shared by C++ and GLSL.
//
//   f = (1 − t) [ (1 − F(θo)) ρ/π + D G2 F(wo·h) / (4 cosθo cosθi) ] + t · glass
//
// F is Schlick's with f90 (fresnel.glsl), so f0 = 0 gives exactly Lambert. The opaque part is
// two-sided (wo below the surface is mirrored up); the glass part knows inside from outside.
#ifndef RAYLAB_BSDF_GLSL
#define RAYLAB_BSDF_GLSL
#include "compat.glsl"
#include "sampling.glsl"
#include "fresnel.glsl"
#include "ggx.glsl"
#include "bsdf_sample.glsl"
#include "dielectric.glsl"
RL_NAMESPACE_BEGIN

#ifdef RAYLAB_EXERCISE_LAMBERT
#include RAYLAB_EXERCISE_LAMBERT   // a pupil's lambertBrdf (exercises/README.md)
#endif

struct BsdfParams {
    vec3 albedo;
    vec3 f0;
    float alpha;          // GGX width, already clamped (ggxAlpha)
    float transmission;   // probability of the glass part
    float ior;
#ifdef __cplusplus   // C++ callers that name only the material get the default estimator
    int diffuseSampling = RAYLAB_DIFFUSE_COSINE;
    int ggxSampling = RAYLAB_GGX_VNDF;
#else
    int diffuseSampling;  // render.diffuse_sampling: RAYLAB_DIFFUSE_*
    int ggxSampling;      // render.ggx_sampling: RAYLAB_GGX_*
#endif
};

// The metallic workflow of other tools on raylab's f0 model: a metal's base colour becomes its f0
// and it has no diffuse lobe (glTF 2.0, KHR metallic-roughness), blended by `metallic`.
RL_FN BsdfParams bsdfWithMetallic(BsdfParams m, float metallic) {
    m.f0 = mix(m.f0, m.albedo, metallic);
    m.albedo = m.albedo * (1.0f - metallic);
    return m;
}

RL_FN float maxComponent(vec3 v) { return max(v.x, max(v.y, v.z)); }

// Does sampling need a random number to choose a lobe? (Pure Lambert does not, which keeps its
// random stream, and so its images, as they were before specular materials existed.)
RL_FN bool bsdfNeedsLobeChoice(BsdfParams m) {
    return m.transmission > 0.0f || maxComponent(m.f0) > 0.0f;
}

// Fresnel at the viewing angle: weights the diffuse base by (1 − F) and sets the lobe choice.
RL_FN vec3 opaqueViewFresnel(BsdfParams m, float cosO) {
    return fresnelSchlick(m.f0, schlickF90(m.f0), cosO);
}

// Probability of sampling the specular lobe: its share of the two lobes' albedo estimates.
RL_FN float opaqueSpecularProbability(BsdfParams m, float cosO) {
    vec3 F = opaqueViewFresnel(m, cosO);
    float s = maxComponent(F);
    float d = maxComponent((vec3(1.0f) - F) * m.albedo);
    if (s <= 0.0f) return 0.0f;
    if (d <= 0.0f) return 1.0f;
    return s / (s + d);
}

// f·cosθi of the opaque part, both directions above the surface (wo.z > 0, wi.z > 0).
RL_FN vec3 opaqueEval(BsdfParams m, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
#ifdef RAYLAB_EXERCISE_LAMBERT
    vec3 result = (vec3(1.0f) - opaqueViewFresnel(m, wo.z)) * lambertBrdf(m.albedo, wo, wi) * wi.z;
#else
    vec3 result = (vec3(1.0f) - opaqueViewFresnel(m, wo.z)) * m.albedo * (INV_PI * wi.z);
#endif
    if (!ggxIsDelta(m.alpha) && maxComponent(m.f0) > 0.0f) {
        vec3 h = normalize(wo + wi);
        vec3 F = fresnelSchlick(m.f0, schlickF90(m.f0), dot(wo, h));
        // D G2 F / (4 cosθo cosθi) · cosθi
        result += F * (ggxD(h, m.alpha) * ggxG2(wo, wi, m.alpha) / (4.0f * wo.z));
    }
    return result;
}

// The diffuse lobe's directions (render.diffuse_sampling) and their density.
RL_FN vec3 diffuseSample(BsdfParams m, vec2 u) {
    return m.diffuseSampling == RAYLAB_DIFFUSE_UNIFORM ? sampleUniformHemisphere(u) : sampleCosineHemisphere(u);
}
RL_FN float diffusePdf(BsdfParams m, float cosTheta) {
    return m.diffuseSampling == RAYLAB_DIFFUSE_UNIFORM ? pdfUniformHemisphere(cosTheta) : pdfCosineHemisphere(cosTheta);
}

// Density of opaqueSample's non-delta directions.
RL_FN float opaquePdf(BsdfParams m, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    float p = opaqueSpecularProbability(m, wo.z);
    float pdf = (1.0f - p) * diffusePdf(m, wi.z);
    if (p > 0.0f && !ggxIsDelta(m.alpha)) {
        vec3 h = normalize(wo + wi);
        if (m.ggxSampling == RAYLAB_GGX_D_COS)
            pdf += p * ggxDCosPdf(h, m.alpha) / (4.0f * dot(wo, h));   // D cosθh / (4 wo·h)
        else   // reflection of visible normals: D_wo(h) / (4 wo·h) = G1(wo) D(h) / (4 cosθo)
            pdf += p * ggxG1(wo, m.alpha) * ggxD(h, m.alpha) / (4.0f * wo.z);
    }
    return pdf;
}

// wo.z > 0. u.xy picks the direction, uLobe in [0, 1) the lobe.
RL_FN BsdfSample opaqueSample(BsdfParams m, vec3 wo, vec2 u, float uLobe) {
    float p = opaqueSpecularProbability(m, wo.z);
    bool delta = ggxIsDelta(m.alpha);
    if (uLobe < p) {
        if (delta) {
            vec3 F = opaqueViewFresnel(m, wo.z);
            return BsdfSample(vec3(-wo.x, -wo.y, wo.z), F / p, p, LOBE_SPECULAR, true);
        }
        vec3 h = ggxSampleNormal(m.ggxSampling, wo, m.alpha, u);
        vec3 wi = 2.0f * dot(wo, h) * h - wo;
        // Reflected below the surface: no light (this drops every h facing away from wo too).
        if (wi.z <= 0.0f) return bsdfNoSample();
        float pdf = opaquePdf(m, wo, wi);
        if (!(pdf > 0.0f)) return bsdfNoSample();
        return BsdfSample(wi, opaqueEval(m, wo, wi) / pdf, pdf, LOBE_SPECULAR, false);
    }
    vec3 wi = diffuseSample(m, u);
#ifndef RAYLAB_EXERCISE_LAMBERT   // a pupil's lambertBrdf goes through opaqueEval below
    if (p <= 0.0f && m.diffuseSampling == RAYLAB_DIFFUSE_COSINE) {
        // Diffuse only: f·cos/pdf = (1 − F) ρ exactly (the furnace tests rely on exactness).
        return BsdfSample(wi, (vec3(1.0f) - opaqueViewFresnel(m, wo.z)) * m.albedo,
                          pdfCosineHemisphere(wi.z), LOBE_DIFFUSE, false);
    }
#endif
    float pdf = opaquePdf(m, wo, wi);
    if (!(pdf > 0.0f)) return bsdfNoSample();
    return BsdfSample(wi, opaqueEval(m, wo, wi) / pdf, pdf, LOBE_DIFFUSE, false);
}

RL_FN vec3 mirrorZ(vec3 v, float s) { return vec3(v.x, v.y, s * v.z); }

// The glass part is a delta lobe (never evaluated) when α is below GGX_DELTA_ALPHA, and at an
// IOR of 1, where every microfacet passes light straight on (a delta lobe however rough).
RL_FN bool bsdfGlassIsDelta(BsdfParams m) { return ggxIsDelta(m.alpha) || abs(m.ior - 1.0f) < 1e-3f; }
RL_FN bool bsdfRoughGlass(BsdfParams m) { return m.transmission > 0.0f && !bsdfGlassIsDelta(m); }

// f·|cosθi| of the whole BSDF (the delta glass and mirror lobes contribute nothing here).
RL_FN vec3 bsdfEval(BsdfParams m, vec3 wo, vec3 wi) {
    vec3 result = vec3(0.0f);
    if (wo.z * wi.z > 0.0f && m.transmission < 1.0f) {
        float s = wo.z < 0.0f ? -1.0f : 1.0f;
        result = (1.0f - m.transmission) * opaqueEval(m, mirrorZ(wo, s), mirrorZ(wi, s));
    }
    if (bsdfRoughGlass(m)) result += vec3(m.transmission * roughDielectricEval(wo, wi, m.alpha, m.ior));
    return result;
}

RL_FN float bsdfPdf(BsdfParams m, vec3 wo, vec3 wi) {
    float pdf = 0.0f;
    if (wo.z * wi.z > 0.0f && m.transmission < 1.0f) {
        float s = wo.z < 0.0f ? -1.0f : 1.0f;
        pdf = (1.0f - m.transmission) * opaquePdf(m, mirrorZ(wo, s), mirrorZ(wi, s));
    }
    if (bsdfRoughGlass(m)) pdf += m.transmission * roughDielectricPdf(wo, wi, m.alpha, m.ior, m.ggxSampling);
    return pdf;
}

// Weight and pdf of a non-delta direction from the whole mixture, so that sample, eval and pdf
// agree whichever lobe produced it (one-sample MIS over the lobes).
RL_FN BsdfSample bsdfCompleteSample(BsdfParams m, vec3 wo, BsdfSample s) {
    if (s.lobe == LOBE_NONE || s.delta) return s;
    float pdf = bsdfPdf(m, wo, s.wi);
    if (!(pdf > 0.0f)) return bsdfNoSample();
    s.pdf = pdf;
    s.weight = bsdfEval(m, wo, s.wi) / pdf;
    return s;
}

// One sample of the whole BSDF; u = (direction, direction, lobe choice), each in [0, 1).
RL_FN BsdfSample bsdfSample(BsdfParams m, vec3 wo, vec3 u) {
    if (u.z < m.transmission) {
        float uGlass = u.z / m.transmission;
        if (bsdfGlassIsDelta(m)) {
            BsdfSample g = dielectricSample(wo, m.ior, uGlass);
            g.pdf *= m.transmission;   // the weight keeps t/t = 1
            return g;
        }
        return bsdfCompleteSample(m, wo, roughDielectricSample(wo, m.alpha, m.ior, m.ggxSampling, vec2(u.x, u.y), uGlass));
    }
    float uLobe = (u.z - m.transmission) / (1.0f - m.transmission);
    if (wo.z == 0.0f) return bsdfNoSample();
    float s = wo.z < 0.0f ? -1.0f : 1.0f;
    BsdfSample o = opaqueSample(m, mirrorZ(wo, s), vec2(u.x, u.y), uLobe);
    o.wi = mirrorZ(o.wi, s);
    if (bsdfRoughGlass(m) && !o.delta) return bsdfCompleteSample(m, wo, o);
    o.pdf *= 1.0f - m.transmission;   // the weight keeps (1 − t)/(1 − t) = 1
    return o;
}

RL_NAMESPACE_END
#endif
