// Lights without a surface (scene `lights`: point, spot, distant; pbrt-v4 §12.1 and §12.4): their
// GPU record, the scene's limit on their number and the maths host and shader share. C++ and GLSL.
#ifndef RAYLAB_ANALYTIC_LIGHTS_GLSL
#define RAYLAB_ANALYTIC_LIGHTS_GLSL
#include "compat.glsl"
#include "frame.glsl"
RL_NAMESPACE_BEGIN

// They live in one uniform block of fixed size (scene_data.glsl): llvmpipe's 16 storage blocks
// per stage are taken by the other buffers.
const int MAX_ANALYTIC_LIGHTS = 64;

const int ANALYTIC_LIGHT_POINT = 0;
const int ANALYTIC_LIGHT_SPOT = 1;
const int ANALYTIC_LIGHT_DISTANT = 2;

struct GpuAnalyticLight {
    vec4 positionType;   // xyz position (point, spot; camera-relative); w ANALYTIC_LIGHT_*
    vec4 axis;           // xyz unit: the spot's axis; distant: towards the light. w: spot cos(outer),
                         // distant 1 − cos(angular radius) (0: a delta light)
    vec4 emitted;        // rgb: I in W/sr (point, spot); E (delta distant); cone radiance (distant). w: spot cos(inner)
};

#ifdef __cplusplus
// The std140 uniform block of scene_data.glsl: the count, then the lights (vec4s only).
struct AnalyticLightBlock {
    ivec4 info;   // x: lights in use
    GpuAnalyticLight lights[MAX_ANALYTIC_LIGHTS];
};
#endif

// pbrt-v4 SpotLight::I: smoothstep in cosθ from the outer cone (0) to the inner one (1).
RL_FN float spotFalloff(float cosTheta, float cosOuter, float cosInner) {
    if (!(cosInner > cosOuter)) return cosTheta >= cosOuter ? 1.0f : 0.0f;
    float t = clamp((cosTheta - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Radiance of a disc of angular radius r that gives irradiance E to a surface facing it:
// E = ∫cone L cosθ dω = L·π·sin²r, with sin²r = (1 − cos r)(2 − (1 − cos r)).
RL_FN float distantConeRadianceScale(float oneMinusCos) { return 1.0f / (PI * oneMinusCos * (2.0f - oneMinusCos)); }

// Uniform over the cone of directions within angle r of a unit axis (pbrt-v4 SampleUniformCone),
// from 1 − cos r so that small cones keep their precision; pdf 1 / (2π(1 − cos r)).
RL_FN vec3 sampleUniformCone(vec3 axis, float oneMinusCos, vec2 u) {
    float a = u.x * oneMinusCos;   // 1 − cosθ
    float cosTheta = 1.0f - a;
    float sinTheta = sqrt(max(0.0f, a * (2.0f - a)));
    float phi = 2.0f * PI * u.y;
    Frame f = frameFromNormal(axis);
    return normalize(frameToWorld(f, vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta)));
}
RL_FN float uniformConePdf(float oneMinusCos) { return 1.0f / (2.0f * PI * oneMinusCos); }

// Whether a unit direction lies in that cone: 1 − cosθ = |dir − axis|²/2, without cancellation.
RL_FN bool insideCone(vec3 dir, vec3 axis, float oneMinusCos) {
    vec3 e = dir - axis;
    return 0.5f * dot(e, e) <= oneMinusCos;
}

RL_NAMESPACE_END
#endif
