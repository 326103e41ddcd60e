// The display pass's parameters: one std140 uniform block at BINDING_DISPLAY_PARAMS_UBO, the same
// struct in C++ (src/render/display_pass.h fills it) and GLSL (shaders/entry/display.frag reads it).
#ifndef RAYLAB_DISPLAY_PARAMS_GLSL
#define RAYLAB_DISPLAY_PARAMS_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

// Scalars only after the leading ivec2, so std140 and C++ lay it out alike (48 bytes).
struct DisplayParams {
    ivec2 imageSize;
    int mode;           // DEBUG_DISPLAY_* (debug_view_table.glsl)
    float exposure;     // EV stops
    int toneMap;        // TONE_MAP_* (tone_map.glsl)
    float depthScale;   // depth: distance shown as black
    float noiseScale;   // noise: relative standard error shown as full red
    float spp;          // samples per pixel accumulated
    int hasMoments;     // 0 before the first pass, or without a moments buffer
    float heatScale;    // heat maps: the count shown as full red
    int pad0;
    int pad1;
};

RL_NAMESPACE_END
#endif
