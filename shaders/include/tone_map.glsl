// Display transform for 8-bit output: exposure, a tone curve, then the sRGB encoding.
#ifndef RAYLAB_TONE_MAP_GLSL
#define RAYLAB_TONE_MAP_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

const int TONE_MAP_CLAMP = 0;
const int TONE_MAP_REINHARD = 1;
const int TONE_MAP_ACES_FIT = 2;

// Reinhard et al. 2002, the simple global operator x / (1 + x).
RL_FN float toneReinhard(float x) { return x / (1.0f + x); }

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": a rational fit of the ACES RRT+ODT.
RL_FN float toneAcesFit(float x) {
    float v = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return clamp(v, 0.0f, 1.0f);
}

// sRGB transfer function (IEC 61966-2-1), linear [0, 1] to encoded [0, 1].
RL_FN float srgbEncode(float x) {
    x = clamp(x, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

// Linear radiance to an sRGB-encoded display value in [0, 1].
RL_FN float displayValue(float linear, float exposureStops, int op) {
    float x = max(linear, 0.0f) * exp2(exposureStops);
    if (op == TONE_MAP_REINHARD) x = toneReinhard(x);
    else if (op == TONE_MAP_ACES_FIT) x = toneAcesFit(x);
    return srgbEncode(x);
}

RL_NAMESPACE_END
#endif
