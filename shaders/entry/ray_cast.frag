#version 450 core
// Ray-rate benchmark entry (src/bench/ray_rate.cpp): one fragment per ray of a buffer, laid out
// row by row over a framebuffer with no attachments uGridWidth wide; each finds its nearest hit
// through the tracer's own traversal and stores t and the primitive.
// Defines set by the host: the scene's features (include/features.glsl).
#include "../include/bindings.glsl"
#include "../include/scene_intersect.glsl"
#include "../include/ray_cast.glsl"

layout(std430, binding = BINDING_CAST_RAYS) readonly buffer CastRayBuffer { CastRay castRays[]; };
layout(std430, binding = BINDING_CAST_HITS) writeonly buffer CastHitBuffer { CastHit castHits[]; };
uniform uint uRayCount;
uniform uint uGridWidth;

void main() {
    uint i = uint(gl_FragCoord.y) * uGridWidth + uint(gl_FragCoord.x);
    if (i >= uRayCount) return;
    CastRay r = castRays[i];
    TraceRecord rec;
    bool hit = traceScene(Ray(r.originTMin.xyz, r.dirTMax.xyz), r.dirTMax.w, false, rec);
    castHits[i] = CastHit(hit ? rec.t : CAST_MISS, rec.instance, rec.primitive, 0u);
}
