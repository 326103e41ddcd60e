#version 450 core
// Test entry point: traces a buffer of rays through the scene's BVH (the tracer's own code) and
// writes what it found. Defines set by the host: the scene features (features.glsl), every one on
// by default (tests/support/gpu_trace.h).
#include "../../shaders/include/bindings.glsl"
#include "../../shaders/include/scene_intersect.glsl"

layout(local_size_x = 64) in;

struct TestRay {
    vec4 origin;   // xyz; w unused
    vec4 dir;      // xyz; w: tMax of the shadow query
};
layout(std430, binding = BINDING_TEST_INPUT) readonly buffer TestRayBuffer { TestRay testRays[]; };
// x: t of the nearest hit (-1 for none); y: instance (bits); z: primitive (bits); w: occluded
layout(std430, binding = BINDING_TEST_OUTPUT) writeonly buffer TestResultBuffer { vec4 testResults[]; };
uniform uint uRayCount;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uRayCount) return;
    Ray r = Ray(testRays[i].origin.xyz, testRays[i].dir.xyz);
    TraceRecord rec;
    bool hit = traceScene(r, FLOAT_MAX, false, rec);
    bool occ = occluded(r, testRays[i].dir.w);
    testResults[i] = vec4(hit ? rec.t : -1.0f, uintBitsToFloat(rec.instance), uintBitsToFloat(rec.primitive),
                          occ ? 1.0f : 0.0f);
}
