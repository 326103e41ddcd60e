#version 450 core
// The viewer's display pass: the accumulated image (or a debug view of it) to 8-bit display
// values, one fragment per traced pixel, drawn into an RGBA8 texture that ImGui shows.
// Defines set by the host: none.
#include "../include/compat.glsl"
#include "../include/bindings.glsl"
#include "../include/tone_map.glsl"

layout(binding = BINDING_ACCUM_TEXTURE) uniform sampler2D uAccumTex;   // running mean (RGBA32F)
layout(std430, binding = BINDING_DEBUG_MOMENTS) readonly buffer DebugMomentsBuffer { vec4 debugMoments[]; };

uniform ivec2 uImageSize;
uniform int uView;          // ui/app/debug_view.h
uniform float uExposure;    // EV stops
uniform int uToneMap;       // TONE_MAP_*
uniform float uDepthScale;  // depth view: distance shown as black
uniform float uNoiseScale;  // noise view: relative standard error shown as full red
uniform float uSpp;         // samples per pixel accumulated
uniform int uHasMoments;    // 0 before the first pass
uniform float uHeatScale;   // box / triangle heat maps: the count shown as full red

layout(location = 0) out vec4 outColor;

vec3 displayRgb(vec3 linear) {
    return vec3(displayValue(linear.r, uExposure, uToneMap), displayValue(linear.g, uExposure, uToneMap),
                displayValue(linear.b, uExposure, uToneMap));
}

// Blue → green → yellow → red, for t in [0, 1] (the legend in the debug panel matches).
vec3 heat(float t) {
    t = clamp(t, 0.0f, 1.0f);
    return clamp(vec3(2.0f * t - 0.5f, t < 0.5f ? 2.0f * t : 2.0f - 2.0f * t + 0.5f, 1.0f - 2.0f * t), 0.0f, 1.0f);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = texelFetch(uAccumTex, p, 0).rgb;
    vec4 m = uHasMoments != 0 ? debugMoments[p.y * uImageSize.x + p.x] : vec4(0.0f);
    vec3 rgb;
    if (uView == 1 || uView == 4 || uView == 12 || uView == 13) {   // normals, material / object id, uv: display colours
        rgb = c;
    } else if (uView == 10 || uView == 11) { // box / triangle tests per camera ray (r / g)
        rgb = heat((uView == 10 ? c.r : c.g) / uHeatScale);
    } else if (uView == 2) {                 // albedo: reflectance, sRGB-encoded, no exposure
        rgb = vec3(srgbEncode(c.r), srgbEncode(c.g), srgbEncode(c.b));
    } else if (uView == 3) {                 // depth: near is white
        rgb = vec3(c.r > 0.0f ? 1.0f - clamp(c.r / uDepthScale, 0.0f, 1.0f) : 0.0f);
    } else if (uView == 5) {                 // NaN / Inf: magenta where any sample was non-finite
        float y = dot(displayRgb(c), vec3(0.2126f, 0.7152f, 0.0722f));
        rgb = m.y > 0.0f ? vec3(1.0f, 0.0f, 1.0f) : vec3(0.35f * y);
    } else if (uView == 6) {                 // noise: relative standard error of the mean luminance
        float mean = dot(c, vec3(0.2126f, 0.7152f, 0.0722f));
        float variance = max(m.x - mean * mean, 0.0f) * uSpp / max(uSpp - 1.0f, 1.0f);
        float relErr = sqrt(variance / max(uSpp, 1.0f)) / max(mean, 1e-4f);
        rgb = heat(relErr / uNoiseScale);
    } else {
        rgb = displayRgb(c);
    }
    outColor = vec4(rgb, 1.0f);
}
