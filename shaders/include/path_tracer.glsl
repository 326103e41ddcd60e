// The progressive path tracer shared by both entry points (trace.frag, trace.comp):
// one pass adds uRpp samples to every pixel's running mean in the accumulation image.
// Estimator: the rendering equation by Monte Carlo, one path per sample, BSDF sampling only.
#ifndef RAYLAB_PATH_TRACER_GLSL
#define RAYLAB_PATH_TRACER_GLSL
#include "compat.glsl"
#include "random.glsl"
#include "frame.glsl"
#include "sampling.glsl"
#include "ray.glsl"
#include "sphere.glsl"
#include "camera.glsl"
#include "sky.glsl"
#include "scene_types.glsl"

// --- Host contract (render/path_tracer.cpp sets all of these every pass) -------------------
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
uniform int uSkyType;
uniform vec3 uSkyColor;
uniform vec3 uSkyTop;
uniform vec3 uSkyBottom;

struct Hit {
    float t;
    vec3 position;   // on the surface
    vec3 normal;     // geometric, unit, pointing out of the object
    vec3 error;      // bound on the position's rounding error, per coordinate
    uint material;
};

bool intersectScene(Ray ray, out Hit hit) {
    hit.t = FLOAT_MAX;
    int nearest = -1;
    for (int i = 0; i < uSphereCount; ++i) {
        vec4 s = spheres[i].centerRadius;
        float t = intersectSphere(ray, s.xyz, s.w, 0.0f, hit.t);
        if (t > 0.0f) {
            hit.t = t;
            nearest = i;
        }
    }
    if (nearest < 0) return false;
    vec4 s = spheres[nearest].centerRadius;
    hit.position = sphereSurfacePoint(rayAt(ray, hit.t), s.xyz, s.w);
    hit.normal = normalize(hit.position - s.xyz);
    hit.error = sphereHitError(s.xyz, s.w);
    hit.material = spheres[nearest].info.x;
    return true;
}

// Radiance along one camera path (Kajiya 1986). beta is the path throughput:
// the product of f·cosθ/pdf over the bounces so far.
vec3 traceRadiance(Ray ray, inout Rng rng, inout uint rays) {
    SkyParams sky = SkyParams(uSkyType, uSkyColor, uSkyTop, uSkyBottom);
    vec3 radiance = vec3(0.0f);
    vec3 beta = vec3(1.0f);
    for (int bounce = 0;; ++bounce) {
        Hit hit;
        ++rays;
        if (!intersectScene(ray, hit)) {
            radiance += beta * skyRadiance(sky, normalize(ray.dir));
            break;
        }
        GpuMaterial m = materials[hit.material];
        radiance += beta * m.emission.rgb;
        if (bounce >= uMaxBounces) break;

        // Lambert, cosine-weighted: f·cosθ/pdf = (ρ/π)·cosθ / (cosθ/π) = ρ.
        vec3 n = dot(hit.normal, ray.dir) < 0.0f ? hit.normal : -hit.normal;
        vec3 dir = frameToWorld(frameFromNormal(n), sampleCosineHemisphere(rngNext2(rng)));
        beta *= m.albedo.rgb;

        // Russian roulette (pbrt-v4 §14.1.4 style): survive with q = max throughput, at most
        // 0.95, and divide by q so the estimate stays unbiased.
        if (bounce + 1 >= uRrDepth) {
            float q = min(max(beta.r, max(beta.g, beta.b)), 0.95f);
            if (rngNextFloat(rng) >= q) break;
            beta /= q;
        }
        ray = Ray(offsetRayOrigin(hit.position, n, hit.error), dir);
    }
    return radiance;
}

void tracePixelPass(ivec2 pixel) {
    CameraBasis cam = CameraBasis(uCamOrigin, uCamRight, uCamUp, uCamForward, uCamTanHalfFovY,
                                  uCamAspect);
    vec3 sum = vec3(0.0f);
    uint rays = 0u;
    uint nonFinite = 0u;
    for (int s = 0; s < uRpp; ++s) {
        Rng rng = rngCreate(uvec2(pixel), uSampleStart + uint(s), uSeed);
        // A fresh jittered position inside the pixel for every sample (box filter).
        vec2 ndc = (vec2(pixel) + rngNext2(rng)) / vec2(uImageSize) * 2.0f - 1.0f;
        vec3 L = traceRadiance(cameraRay(cam, ndc), rng, rays);
#ifdef RAYLAB_INJECT_NONFINITE
        // Tests only: every RAYLAB_INJECT_NONFINITE-th sample of a row becomes NaN or +Inf.
        uint k = uSampleStart + uint(s) + uint(pixel.x);
        if (k % uint(RAYLAB_INJECT_NONFINITE) == 0u)
            L = vec3(uintBitsToFloat((k & 1u) == 0u ? 0x7fc00000u : 0x7f800000u));
#endif
        if (any(isnan(L)) || any(isinf(L))) {
            ++nonFinite;
            L = vec3(0.0f);
        }
        sum += L;
    }
    // Running mean over all samples: mean_n = mean_m + (sum − k·mean_m) / n, with n = m + k.
    vec3 mean = sum / float(uRpp);
    if (uSampleStart > 0u) {
        vec3 old = imageLoad(uAccum, pixel).rgb;
        mean = old + (sum - float(uRpp) * old) / float(uSampleStart + uint(uRpp));
    }
    imageStore(uAccum, pixel, vec4(mean, 1.0f));
    if (nonFinite > 0u) atomicAdd(nonFiniteSamples, nonFinite);
    atomicAdd(raysTraced, rays);
}

#endif
