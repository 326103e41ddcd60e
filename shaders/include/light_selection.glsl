// Which light next-event estimation samples: the sky (when it is a light) or one of the bounded
// lights (emissive spheres, then emissive triangles), these by power through the alias table
// the host builds (render/light_list.h). GLSL only.
#ifndef RAYLAB_LIGHT_SELECTION_GLSL
#define RAYLAB_LIGHT_SELECTION_GLSL
#include "scene_data.glsl"
#include "features.glsl"

int triangleLightCount() {
#ifdef RAYLAB_EMISSIVE_TRIANGLES
    return uTriangleLightCount;
#else
    return 0;
#endif
}

int boundedLightCount() { return uLightCount + triangleLightCount(); }

// The sky's power is not comparable with a bounded light's (it depends on the scene's extent), so
// as pbrt-v4's BVHLightSampler does, the sky gets 1/2 beside bounded lights and 1 alone.
float skySelectionPmf() {
    if (!uSkyIsLight) return 0.0f;
    return boundedLightCount() > 0 ? 0.5f : 1.0f;
}

// Probability with which bounded light i is picked (alias table pmf × not picking the sky).
float boundedLightPmf(int i) { return (1.0f - skySelectionPmf()) * lightAlias[i].z; }

// A light from two uniform numbers: -1 for the sky, else the bounded light's index. pmf is the
// probability of what was picked. u decides sky or not and the alias table's column; v its coin.
int selectLight(float u, float v, out float pmf) {
    float pSky = skySelectionPmf();
    if (u < pSky) {
        pmf = pSky;
        return -1;
    }
    int n = boundedLightCount();
    float uBounded = (u - pSky) / (1.0f - pSky);
    int i = min(int(uBounded * float(n)), n - 1);
    vec4 entry = lightAlias[i];
    if (v >= entry.x) i = int(entry.y);
    pmf = boundedLightPmf(i);
    return i;
}

#endif
