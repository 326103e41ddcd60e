// Which light next-event estimation samples: the sky (when it is a light) or one of the bounded
// lights (emissive spheres, then emissive triangles, then point, spot and distant lights). GLSL only.
// With RAYLAB_LIGHT_POWER_SELECTION (the lights differ in power) bounded lights are picked by
// power through the alias table the host builds (render/light_list.h), and the sky gets 1/2 beside
// them: its power is not comparable with a bounded light's (it depends on the scene's extent), so
// pbrt-v4's BVHLightSampler gives infinite lights a fixed share the same way. Without it (all
// lights of equal power) picking by power is picking uniformly: every light, the sky counted as
// one, gets 1/(n + 1), and the table is never read; this is the selection raylab had before
// triangle lights, same random numbers, so such scenes render as before bit for bit. (Measured
// on the Veach scene: the table path costs no throughput beyond the noise of the shared machine,
// bench/materials.md.)
#ifndef RAYLAB_LIGHT_SELECTION_GLSL
#define RAYLAB_LIGHT_SELECTION_GLSL
#include "sampler.glsl"
#include "scene_data.glsl"
#include "features.glsl"

// Slot floor(u·n) of n, and u rescaled to [0, 1) within that slot for the next use (the clamp:
// the rescale's rounding can reach 1, which a [0, 1) sample never is).
int pickSlot(inout float u, int n) {
    float w = u * float(n);
    int i = min(int(w), n - 1);
    u = clamp(w - float(i), 0.0f, 0.99999994f);
    return i;
}

// Emissive spheres (bounded lights 0 … sphereLightCount() − 1) and the sky as a light, each
// compiled in only where the scene has it (RAYLAB_SPHERE_LIGHTS, RAYLAB_SKY_LIGHT): llvmpipe runs
// the code of every light kind at every light sample, taken or not.
int sphereLightCount() {
#if RAYLAB_SPHERE_LIGHTS
    return params.lightCount;
#else
    return 0;
#endif
}

bool skyIsLight() { return RAYLAB_SKY_LIGHT != 0 && params.skyIsLight; }

int triangleLightCount() {
#if RAYLAB_EMISSIVE_TRIANGLES
    return params.triangleLightCount;
#else
    return 0;
#endif
}

#if RAYLAB_ANALYTIC_LIGHTS
int analyticLightCount() { return analyticLightInfo.x; }
#else
int analyticLightCount() { return 0; }
#endif

// Index of the first point, spot or distant light among the bounded lights.
int firstAnalyticLight() { return sphereLightCount() + triangleLightCount(); }

int boundedLightCount() { return firstAnalyticLight() + analyticLightCount(); }

#if RAYLAB_LIGHT_POWER_SELECTION
float skySelectionPmf() {
    if (!skyIsLight()) return 0.0f;
    return boundedLightCount() > 0 ? 0.5f : 1.0f;
}

// Probability with which bounded light i is picked (alias table pmf × not picking the sky).
float boundedLightPmf(int i) { return (1.0f - skySelectionPmf()) * lightAliasAt(i).z; }

// A light: -1 for the sky, else the bounded light's index; pmf is the probability of the pick.
// u, the first number of the light point's pair, decides sky or not and the alias table's column,
// and comes back rescaled to [0, 1) within the part of [0, 1) it fell in, so the point on the light
// takes it again (pbrt-v4's SampleDiscrete with uRemapped): the choice and the point are one
// stratified 2D sample, and no dimension of its own is drawn for the choice. A coin picks the
// column or its alias; one read of the table (an entry holds the pmf of its column and of its alias).
int selectLight(inout Sampler smp, inout float u, out float pmf) {
    float v = sampleCoin(smp);
    float pSky = skySelectionPmf();
    if (u < pSky) {
        pmf = pSky;
        u = clamp(u / pSky, 0.0f, 0.99999994f);
        return -1;
    }
    u = (u - pSky) / (1.0f - pSky);
    int i = pickSlot(u, boundedLightCount());
    vec4 entry = lightAliasAt(i);
    bool keep = v < entry.x;
    pmf = (1.0f - pSky) * (keep ? entry.z : entry.w);
    return keep ? i : int(entry.y);
}
#else
int uniformLightCount() { return boundedLightCount() + (skyIsLight() ? 1 : 0); }
float skySelectionPmf() { return skyIsLight() ? 1.0f / float(uniformLightCount()) : 0.0f; }
float boundedLightPmf(int i) { return 1.0f / float(uniformLightCount()); }

// The same choice uniformly: u picks the light and comes back rescaled within its share.
int selectLight(inout Sampler smp, inout float u, out float pmf) {
    int n = uniformLightCount();
    int k = pickSlot(u, n);
    pmf = 1.0f / float(n);
    return k < boundedLightCount() ? k : -1;
}
#endif

#endif
