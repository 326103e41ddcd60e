// Which lobe of the BSDF (bsdf.glsl) a sample came from, and with what probability bsdfSample
// chooses it: for the path inspector's table and the BRDF explorer. Shared by C++ and GLSL.
#ifndef RAYLAB_BSDF_LOBES_GLSL
#define RAYLAB_BSDF_LOBES_GLSL
#include "compat.glsl"
#include "bsdf.glsl"
RL_NAMESPACE_BEGIN

// Probability that bsdfSample(m, wo, ·) takes `lobe`. The glass lobes report the glass part's
// probability t (inside it, Fresnel chooses reflection or refraction).
RL_FN float bsdfLobeProbability(BsdfParams m, vec3 wo, int lobe) {
    float t = m.transmission;
    if (lobe == LOBE_GLASS_REFLECT || lobe == LOBE_GLASS_TRANSMIT) return t;
    if (!bsdfNeedsLobeChoice(m)) return lobe == LOBE_DIFFUSE ? 1.0f : 0.0f;
    float p = opaqueSpecularProbability(m, abs(wo.z));
    if (lobe == LOBE_SPECULAR) return (1.0f - t) * p;
    if (lobe == LOBE_DIFFUSE) return (1.0f - t) * (1.0f - p);
    return 0.0f;
}

RL_NAMESPACE_END
#endif
