// Equirectangular (latitude–longitude) environment images: directions to image coordinates and
// back. Shared by C++ and GLSL. u runs once around the up axis (+y), starting behind the default
// camera (−z) at u = 0.5 ... so that the image centre is straight ahead (−z); v runs from straight
// up (v = 0, the image's top row) to straight down (v = 1). `rotation` (radians) turns the image
// about +y.
#ifndef RAYLAB_ENVIRONMENT_MAP_GLSL
#define RAYLAB_ENVIRONMENT_MAP_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

RL_FN vec2 equirectFromDirection(vec3 d, float rotation) {
    float phi = atan(d.x, -d.z) + rotation;   // (−π, π] around +y, 0 towards −z
    float u = phi * (0.5f * INV_PI) + 0.5f;
    u = u - floor(u);
    float v = acos(clamp(d.y, -1.0f, 1.0f)) * INV_PI;
    return vec2(u, v);
}

RL_FN vec3 directionFromEquirect(vec2 uv, float rotation) {
    float phi = (uv.x - 0.5f) * 2.0f * PI - rotation;
    float theta = uv.y * PI;
    float s = sin(theta);
    return vec3(s * sin(phi), cos(theta), -s * cos(phi));
}

RL_NAMESPACE_END
#endif
