// Radiance arriving from directions that leave the scene.
#ifndef RAYLAB_SKY_GLSL
#define RAYLAB_SKY_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

const int SKY_CONSTANT = 0;
const int SKY_GRADIENT = 1;
const int SKY_MAP = 2;   // an equirectangular image, looked up in GLSL (integrator.glsl)

struct SkyParams {
    int type;
    vec3 color;    // constant: radiance
    vec3 top;      // gradient: radiance towards +y
    vec3 bottom;   // gradient: radiance towards -y
};

// Gradient: linear in the direction's y, bottom at y = -1, top at y = +1.
RL_FN vec3 skyRadiance(SkyParams sky, vec3 unitDir) {
    if (sky.type == SKY_CONSTANT) return sky.color;
    float t = clamp(0.5f * (unitDir.y + 1.0f), 0.0f, 1.0f);
    return mix(sky.bottom, sky.top, t);
}

RL_NAMESPACE_END
#endif
