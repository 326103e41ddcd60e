// Debug views of the viewer. RAYLAB_DEBUG_VIEWS: the view selected by uDebugView (normals, albedo,
// depth, material id) is traced in place of the beauty path. RAYLAB_DEBUG_MOMENTS: the beauty path
// also keeps per-pixel moments (mean luminance², non-finite count) for the noise and NaN/Inf views.
// The viewer compiles a tracer variant per need; the plain beauty variant and raylab-render define
// neither: then this file adds nothing. (Always included: the include expander does not see #if.) Binding points 16-19 belong to the viewer. GLSL only.
#ifndef RAYLAB_DEBUG_VIEWS_GLSL
#define RAYLAB_DEBUG_VIEWS_GLSL
#include "compat.glsl"
#include "random.glsl"
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

#ifdef RAYLAB_DEBUG_VIEWS
uniform int uDebugView;
uniform int uDebugBounce;

// The integrator's contributions, filtered by bounce for views 7-9 (bounce 0: the camera ray).
bool debugKeepBounce(int bounce) {
    if (uDebugView == DEBUG_BOUNCE_K) return bounce == uDebugBounce;
    if (uDebugView == DEBUG_DIRECT) return bounce <= 1;
    if (uDebugView == DEBUG_INDIRECT) return bounce >= 2;
    return true;
}
#define RAYLAB_ADD_RADIANCE(radiance, bounce, value) if (debugKeepBounce(bounce)) radiance += (value)

vec3 traceRadiance(Ray ray, inout Rng rng, inout uint rays);   // integrator.glsl, included after this file

// A colour per id that neighbouring ids do not share (golden-ratio hue steps).
vec3 debugIdColor(uint id) {
    float h = fract(float(id) * 0.618034f + 0.1f);
    vec3 k = clamp(abs(fract(h + vec3(0.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
    return 0.25f + 0.75f * k;
}

// One sample of the selected view for a camera ray. Depth is the distance along the ray (0 for a
// miss); the display shader maps it to grey.
vec3 debugSample(Ray ray, inout Rng rng, inout uint rays) {
    if (uDebugView == DEBUG_BEAUTY || uDebugView >= DEBUG_FIRST_DISPLAY_ONLY)
        return traceRadiance(ray, rng, rays);   // views 7-9: filtered by the hook above
    Hit hit;
    ++rays;
    if (!intersectScene(ray, hit)) return vec3(0.0f);
    if (uDebugView == DEBUG_NORMALS) return hit.normal * 0.5f + 0.5f;
    if (uDebugView == DEBUG_ALBEDO) return materials[hit.material].albedo.rgb;
    if (uDebugView == DEBUG_DEPTH) return vec3(hit.t);
    return debugIdColor(hit.material);
}

#endif

#ifdef RAYLAB_DEBUG_MOMENTS
// Per pixel (row-major from the bottom row): x = running mean of luminance², y = non-finite
// samples so far. Cleared by the host whenever accumulation restarts.
layout(std430, binding = 16) buffer DebugMomentsBuffer { vec4 debugMoments[]; };

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
    uint i = uint(pixel.y * uImageSize.x + pixel.x);
    vec4 old = uSampleStart > 0u ? debugMoments[i] : vec4(0.0f);
    float n = float(uSampleStart + uint(uRpp));
    debugMoments[i] = vec4(old.x + (m.sumSq - float(uRpp) * old.x) / n, old.y + float(m.nonFinite), 0.0f, 0.0f);
}
#endif

#endif
