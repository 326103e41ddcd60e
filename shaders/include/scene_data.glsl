// The host contract of the path tracer: every buffer and uniform the tracer reads, with the
// binding points render/path_tracer.cpp and render/gpu_scene.cpp use. GLSL only.
#ifndef RAYLAB_SCENE_DATA_GLSL
#define RAYLAB_SCENE_DATA_GLSL
#include "scene_types.glsl"

layout(rgba32f, binding = 0) uniform image2D uAccum;   // running mean, rgb; a = 1
layout(std430, binding = 1) readonly buffer SphereBuffer { GpuSphere spheres[]; };
layout(std430, binding = 2) readonly buffer MaterialBuffer { GpuMaterial materials[]; };
layout(std430, binding = 3) buffer CounterBuffer {
    uint nonFiniteSamples;   // samples that were NaN or Inf and were replaced by 0
    uint raysTraced;         // ray casts this pass (camera and bounce rays)
};

uniform ivec2 uImageSize;
uniform uint uSampleStart;   // samples per pixel already in uAccum
uniform int uRpp;            // samples per pixel in this pass
uniform uint uSeed;
uniform int uMaxBounces;
uniform int uRrDepth;
uniform int uSphereCount;
uniform vec3 uCamOrigin;
uniform vec3 uCamRight;
uniform vec3 uCamUp;
uniform vec3 uCamForward;
uniform float uCamTanHalfFovY;
uniform float uCamAspect;
uniform float uCamLensRadius;      // thin lens (RAYLAB_FEATURE_DOF): lens radius, world units
uniform float uCamFocusDistance;   // distance of the sharp plane along the view axis
uniform float uCamPixelSpread;     // angle one pixel subtends (ray-cone texture LOD), radians
uniform int uSkyType;
uniform vec3 uSkyColor;
uniform vec3 uSkyTop;
uniform vec3 uSkyBottom;

#endif
