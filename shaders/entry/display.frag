#version 450 core
// The display pass: the accumulated image (or a debug view of it) to 8-bit display values, one
// fragment per traced pixel, drawn into an RGBA8 texture (src/render/display_pass.h).
// Defines set by the host: none.
#include "../include/bindings.glsl"
#include "../include/compat.glsl"
#include "../include/debug_view_table.glsl"
#include "../include/display_params.glsl"
#include "../include/tone_map.glsl"

layout(binding = BINDING_ACCUM_TEXTURE) uniform sampler2D uAccumTex;   // running mean (RGBA32F)
layout(std430, binding = BINDING_DEBUG_MOMENTS) readonly buffer DebugMomentsBuffer { vec4 debugMoments[]; };
layout(std140, binding = BINDING_DISPLAY_PARAMS_UBO) uniform DisplayParamsBlock { DisplayParams display; };

layout(location = 0) out vec4 outColor;

vec3 displayRgb(vec3 linear) {
    return vec3(displayValue(linear.r, display.exposure, display.toneMap),
                displayValue(linear.g, display.exposure, display.toneMap),
                displayValue(linear.b, display.exposure, display.toneMap));
}

// Blue → green → yellow → red, for t in [0, 1] (ui/panels/heat_legend.cpp draws the same ramp).
vec3 heat(float t) {
    t = clamp(t, 0.0f, 1.0f);
    return clamp(vec3(2.0f * t - 0.5f, t < 0.5f ? 2.0f * t : 2.0f - 2.0f * t + 0.5f, 1.0f - 2.0f * t), 0.0f, 1.0f);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = texelFetch(uAccumTex, p, 0).rgb;
    vec4 m = display.hasMoments != 0 ? debugMoments[p.y * display.imageSize.x + p.x] : vec4(0.0f);
    int mode = display.mode;
    vec3 rgb;
    if (mode == DEBUG_DISPLAY_RAW) {
        rgb = c;
    } else if (mode == DEBUG_DISPLAY_HEAT_R || mode == DEBUG_DISPLAY_HEAT_G) {
        rgb = heat((mode == DEBUG_DISPLAY_HEAT_R ? c.r : c.g) / display.heatScale);
    } else if (mode == DEBUG_DISPLAY_SRGB) {
        rgb = vec3(srgbEncode(c.r), srgbEncode(c.g), srgbEncode(c.b));
    } else if (mode == DEBUG_DISPLAY_DEPTH) {
        rgb = vec3(c.r > 0.0f ? 1.0f - clamp(c.r / display.depthScale, 0.0f, 1.0f) : 0.0f);
    } else if (mode == DEBUG_DISPLAY_NON_FINITE) {
        float y = dot(displayRgb(c), vec3(0.2126f, 0.7152f, 0.0722f));
        rgb = m.y > 0.0f ? vec3(1.0f, 0.0f, 1.0f) : vec3(0.35f * y);
    } else if (mode == DEBUG_DISPLAY_NOISE) {   // relative standard error of the mean luminance
        float mean = dot(c, vec3(0.2126f, 0.7152f, 0.0722f));
        float variance = max(m.x - mean * mean, 0.0f) * display.spp / max(display.spp - 1.0f, 1.0f);
        float relErr = sqrt(variance / max(display.spp, 1.0f)) / max(mean, 1e-4f);
        rgb = heat(relErr / display.noiseScale);
    } else {
        rgb = displayRgb(c);
    }
    outColor = vec4(rgb, 1.0f);
}
