// Debug views of the viewer. RAYLAB_DEBUG_VIEWS: the view selected by uDebugView (normals, albedo,
// depth, material id, object id, uv, box and triangle tests of the camera ray) is traced in place of the
// beauty path. RAYLAB_DEBUG_MOMENTS: the beauty path
// also keeps per-pixel moments (mean luminance², non-finite count) for the noise and NaN/Inf views.
// The viewer compiles a tracer variant per need; the plain beauty variant and raylab-render define
// neither: then this file adds nothing. (Always included: the include expander does not see #if.) Binding points 16-19 belong to the viewer. GLSL only.
#ifndef RAYLAB_DEBUG_VIEWS_GLSL
#define RAYLAB_DEBUG_VIEWS_GLSL
#include "compat.glsl"
#include "sampler.glsl"
#include "ray.glsl"
#include "scene_data.glsl"
#include "scene_intersect.glsl"

// Must match ui/app/debug_view.h. Views >= DEBUG_FIRST_DISPLAY_ONLY trace the beauty path and
// are drawn from the moments by the display shader.
const int DEBUG_BEAUTY = 0;
const int DEBUG_NORMALS = 1;
const int DEBUG_ALBEDO = 2;
const int DEBUG_DEPTH = 3;
const int DEBUG_MATERIAL_ID = 4;
const int DEBUG_FIRST_DISPLAY_ONLY = 5;   // 5 NaN/Inf, 6 noise
const int DEBUG_BOUNCE_K = 7;             // only light that reached the eye after uDebugBounce bounces
const int DEBUG_DIRECT = 8;               // emitters and sky seen directly or after one bounce
const int DEBUG_INDIRECT = 9;             // light after two or more bounces
// 10, 11: box and triangle tests of the camera ray; both store (boxes, triangles, 0) and need
// RAYLAB_COUNT_TRAVERSAL (else 0); the display shader picks the channel. 12: fract(uv), 0.
const int DEBUG_BOXES = 10;
const int DEBUG_TRIANGLES = 11;
const int DEBUG_UV = 12;
const int DEBUG_OBJECT_ID = 13;           // a colour per object: spheres, then meshes (instanceObjectId)

#if RAYLAB_DEBUG_VIEWS
uniform int uDebugView;
uniform int uDebugBounce;

// The integrator's contributions, filtered by bounce for views 7-9 (bounce 0: the camera ray).
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
// Binding 17: the largest box (x) and triangle (y) count of one camera ray since the host last
// cleared it: the heat maps' automatic scale.
layout(std430, binding = BINDING_DEBUG_HEAT_MAX) buffer DebugHeatMaxBuffer { uint debugHeatMax[2]; };
#endif

// One sample of the selected view for a camera ray. Depth is the distance along the ray (0 for a
// miss); the display shader maps it to grey. The heat maps count the tests of this ray only (the
// primary ray), not of the path's later bounces or shadow rays.

vec3 debugSample(Ray ray, inout Sampler smp, inout uint rays) {
    if (uDebugView == DEBUG_BEAUTY || (uDebugView >= DEBUG_FIRST_DISPLAY_ONLY && uDebugView <= DEBUG_INDIRECT))
        return traceRadiance(ray, smp, rays);   // views 7-9: filtered by the hook above
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
