// Debug views. RAYLAB_DEBUG_VIEWS: the view selected by uDebugView (debug_view_table.glsl) is
// traced in place of the beauty path; RAYLAB_DEBUG_MOMENTS: the beauty path also keeps per-pixel
// moments for the noise and NaN/Inf views. Without either this file adds only the view ids. GLSL only.
#ifndef RAYLAB_DEBUG_VIEWS_GLSL
#define RAYLAB_DEBUG_VIEWS_GLSL
#include "bindings.glsl"
#include "compat.glsl"
#include "debug_view_table.glsl"
#include "frame.glsl"
#include "sampler.glsl"
#include "ray.glsl"
#include "sampling.glsl"
#include "scene_data.glsl"
#include "scene_intersect.glsl"
#include "bsdf.glsl"
// Under the condition the integrator includes it with: a file is inlined once, where first named.
#if RAYLAB_FEATURE_TEXTURES
#include "material_textures.glsl"
#endif

#define RAYLAB_DEBUG_VIEW_ID(id, NAME, Name, name, traced, moments, counts, display, legend) const int DEBUG_##NAME = id;
RAYLAB_DEBUG_VIEW_TABLE(RAYLAB_DEBUG_VIEW_ID)
#undef RAYLAB_DEBUG_VIEW_ID

#if RAYLAB_DEBUG_VIEWS
uniform int uDebugView;     // DEBUG_*, set through render/debug_buffers.h
uniform int uDebugBounce;   // the k of DEBUG_BOUNCE_K

// The integrator's contributions, filtered by bounce for the bounce views (bounce 0: the camera ray).
bool debugKeepBounce(int bounce) {
    if (uDebugView == DEBUG_BOUNCE_K) return bounce == uDebugBounce;
    if (uDebugView == DEBUG_DIRECT) return bounce <= 1;
    if (uDebugView == DEBUG_INDIRECT) return bounce >= 2;
    return true;
}
#define RAYLAB_KEEP_BOUNCE(bounce) debugKeepBounce(bounce)

vec3 traceRadiance(Ray ray, inout Sampler smp, inout uint rays);   // integrator.glsl, included after this file

// A colour per id that neighbouring ids do not share (golden-ratio hue steps).
vec3 debugIdColor(uint id) {
    float h = fract(float(id) * 0.618034f + 0.1f);
    vec3 k = clamp(abs(fract(h + vec3(0.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
    return 0.25f + 0.75f * k;
}

#if RAYLAB_COUNT_TRAVERSAL
// The largest box (x) and triangle (y) count of one camera ray since the host last cleared it:
// the heat maps' automatic scale.
layout(std430, binding = BINDING_DEBUG_HEAT_MAX) buffer DebugHeatMaxBuffer { uint debugHeatMax[2]; };
#endif

// Ambient occlusion: the fraction of params.aoRays cosine-weighted rays from the first hit, on the
// side the camera sees, that travel params.aoDistance without hitting anything. Above a plane
// parallel at height h < d its expectation is 1 − P(cosθ > h/d) = (h/d)² (cos²θ is uniform).
// Ray i of sample s is sample s·aoRays + i of the render's sampler in bounce 0's BSDF dimensions,
// so the rays of a pixel are stratified as its bounces are (the independent sampler's stream goes
// on in call order, as before).
float debugAmbientOcclusion(Ray ray, Hit hit, inout Sampler smp, inout uint rays) {
    vec3 n = dot(ray.dir, hit.normal) < 0.0f ? hit.normal : -hit.normal;
    Frame frame = frameFromNormal(n);
    vec3 origin = offsetRayOrigin(hit.position, n, hit.error);
    int open = 0;
    Sampler aoSmp = smp;
    aoSmp.count = smp.count * uint(params.aoRays);
    for (int i = 0; i < params.aoRays; ++i) {
        aoSmp.index = smp.index * uint(params.aoRays) + uint(i);
        vec3 dir = frameToWorld(frame, sampleCosineHemisphere(sample2D(aoSmp, sampleDim(0, SAMPLE_BOUNCE_BSDF))));
        ++rays;
        if (!occluded(Ray(origin, dir), params.aoDistance)) ++open;
    }
    smp.rng = aoSmp.rng;
    return float(open) / float(params.aoRays);
}

// The material's baked occlusion at the first hit, as glTF 2.0 §3.9.3 defines it: 1 + strength ×
// (red − 1); 1 where the material has no map. Only this view reads the map: the path tracer finds
// occlusion by tracing, and multiplying the map in would count it twice.
float debugBakedOcclusion(Ray ray, Hit hit) {
#if RAYLAB_FEATURE_TEXTURES
    uint k1 = materials[hit.material].occlusionTexture;
    if (k1 > 0u) {
        float coneWidth = params.camPixelSpread * hit.t * length(ray.dir);   // the camera ray's cone (ray_cone.glsl)
        float texel = sampleHitTexture(k1, hit, ray.dir, coneWidth).r;
        return 1.0f + materials[hit.material].occlusionStrength * (texel - 1.0f);
    }
#endif
    return 1.0f;
}

// One sample of the selected view for a camera ray. Depth is the distance along the ray (0 for a
// miss); the display shader maps it to grey. The heat maps count the tests of this ray only (the
// primary ray), not of the path's later bounces or shadow rays.

vec3 debugSample(Ray ray, inout Sampler smp, inout uint rays) {
    if (uDebugView == DEBUG_BEAUTY || uDebugView == DEBUG_NON_FINITE || uDebugView == DEBUG_NOISE ||
        uDebugView == DEBUG_BOUNCE_K || uDebugView == DEBUG_DIRECT || uDebugView == DEBUG_INDIRECT)
        return traceRadiance(ray, smp, rays);   // the bounce views: filtered by the hook above
    Hit hit;
    ++rays;
#if RAYLAB_COUNT_TRAVERSAL
    uint boxesBefore = gBoxTests;
    uint trianglesBefore = gTriangleTests;
#endif
    bool found = intersectScene(ray, hit);
    if (uDebugView == DEBUG_BOXES || uDebugView == DEBUG_TRIANGLES) {
#if RAYLAB_COUNT_TRAVERSAL
        uint boxes = gBoxTests - boxesBefore;
        uint tris = gTriangleTests - trianglesBefore;
        atomicMax(debugHeatMax[0], boxes);
        atomicMax(debugHeatMax[1], tris);
        return vec3(float(boxes), float(tris), 0.0f);
#else
        return vec3(0.0f);
#endif
    }
    if (!found) return vec3(0.0f);
    if (uDebugView == DEBUG_UV) return vec3(fract(hit.uv), 0.0f);
    if (uDebugView == DEBUG_NORMALS) return hit.normal * 0.5f + 0.5f;
    if (uDebugView == DEBUG_ALBEDO) return materials[hit.material].albedo.rgb;
    if (uDebugView == DEBUG_DEPTH) return vec3(hit.t);
    if (uDebugView == DEBUG_OBJECT_ID) return debugIdColor(instanceObjectId(instances[hit.instance]));
    if (uDebugView == DEBUG_AO) return vec3(debugAmbientOcclusion(ray, hit, smp, rays));
    if (uDebugView == DEBUG_BAKED_AO) return vec3(debugBakedOcclusion(ray, hit));
    return debugIdColor(hit.material);
}

#endif

#if RAYLAB_DEBUG_MOMENTS
// Per pixel (row-major from the bottom row): x = running mean of luminance², y = non-finite
// samples so far. Cleared by the host whenever accumulation restarts.
layout(std430, binding = BINDING_DEBUG_MOMENTS) buffer DebugMomentsBuffer { vec4 debugMoments[]; };

struct DebugMoments {
    float sumSq;      // sum of luminance² over this pass's samples
    uint nonFinite;
};

DebugMoments debugMomentsBegin() { return DebugMoments(0.0f, 0u); }

void debugMomentsAdd(inout DebugMoments m, vec3 L) {
    if (any(isnan(L)) || any(isinf(L))) {
        ++m.nonFinite;
        return;   // counts as a zero sample, as in the mean
    }
    float y = dot(L, vec3(0.2126f, 0.7152f, 0.0722f));   // Rec. 709 luminance
    m.sumSq += y * y;
}

void debugMomentsStore(DebugMoments m, ivec2 pixel) {
    uint i = uint(pixel.y * params.imageSize.x + pixel.x);
    vec4 old = params.sampleStart > 0u ? debugMoments[i] : vec4(0.0f);
    float n = float(params.sampleStart + uint(params.rpp));
    debugMoments[i] = vec4(old.x + (m.sumSq - float(params.rpp) * old.x) / n, old.y + float(m.nonFinite), 0.0f, 0.0f);
}
#endif

#endif
