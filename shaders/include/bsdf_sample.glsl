// What a BSDF sampling routine returns. Shared by C++ and GLSL.
#ifndef RAYLAB_BSDF_SAMPLE_GLSL
#define RAYLAB_BSDF_SAMPLE_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

const int LOBE_NONE = 0;             // no valid direction (weight 0): the path ends
const int LOBE_DIFFUSE = 1;
const int LOBE_SPECULAR = 2;         // GGX reflection, or the mirror when delta
const int LOBE_GLASS_REFLECT = 3;    // smooth dielectric, reflected (delta)
const int LOBE_GLASS_TRANSMIT = 4;   // smooth dielectric, refracted (delta)

struct BsdfSample {
    vec3 wi;       // local frame, unit
    vec3 weight;   // f·|cosθi| / pdf (for delta lobes: the lobe's value / its probability)
    float pdf;     // solid-angle density of wi; for delta lobes the discrete probability
    int lobe;
    bool delta;    // a delta lobe: light sampling cannot find this direction (no MIS)
};

RL_FN BsdfSample bsdfNoSample() { return BsdfSample(vec3(0.0f), vec3(0.0f), 0.0f, LOBE_NONE, false); }

RL_NAMESPACE_END
#endif
