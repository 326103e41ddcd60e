#version 450 core
// Exercise probe: runs one slot function of the code track on a table of inputs and stores what it
// returns, so the checks (host: src/exercise/exercise_probe.cpp) compare it on the CPU with double
// precision and with the shared reference maths. One invocation per record.
// Defines set by the host: every feature on (render/shader_variant.h allFeatures) and the one
// RAYLAB_EXERCISE_* file define of the exercise being checked (exercises/manifest.tsv).
#include "bindings.glsl"
#include "sphere.glsl"
#include "triangle.glsl"
#include "aabb.glsl"
#include "sampling.glsl"
#include "bsdf.glsl"
#include "camera.glsl"
#ifdef RAYLAB_EXERCISE_RUNNING_MEAN
#include RAYLAB_EXERCISE_RUNNING_MEAN   // a pupil's runningMean, which the tracer keeps in path_tracer.glsl
#endif

layout(local_size_x = 64) in;

struct ProbeInput {
    vec4 v[6];
};
struct ProbeOutput {
    vec4 a;
    vec4 b;
};
layout(std430, binding = BINDING_TEST_INPUT) readonly buffer Inputs { ProbeInput inputs[]; };
layout(std430, binding = BINDING_TEST_OUTPUT) writeonly buffer Outputs { ProbeOutput outputs[]; };

uniform uint uCount;
uniform int uMode;   // the slot: src/exercise/exercise_probe.h ProbeMode

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) return;
    ProbeInput x = inputs[i];
    ProbeOutput y = ProbeOutput(vec4(0.0), vec4(0.0));
    if (uMode == 0) {
        y.a.x = intersectSphere(Ray(x.v[0].xyz, x.v[1].xyz), x.v[2].xyz, x.v[2].w, x.v[0].w, x.v[1].w);
    } else if (uMode == 1) {
        TriangleHit h = TriangleHit(-1.0, 0.0, 0.0, 0.0);
        bool hit = intersectTriangle(Ray(x.v[0].xyz, x.v[1].xyz), x.v[2].xyz, x.v[3].xyz, x.v[4].xyz, x.v[0].w, h);
        y.a = vec4(hit ? 1.0 : 0.0, h.t, h.b1, h.b2);
    } else if (uMode == 2) {
        y.a.x = intersectBox(x.v[0].xyz, x.v[1].xyz, x.v[2].xyz, x.v[3].xyz, x.v[0].w);
    } else if (uMode == 3) {
        vec3 w = sampleCosineHemisphere(x.v[0].xy);
        y.a = vec4(w, pdfCosineHemisphere(w.z));
        y.b.x = pdfCosineHemisphere(x.v[0].z);
    } else if (uMode == 4) {
#ifdef RAYLAB_EXERCISE_LAMBERT
        y.a.xyz = lambertBrdf(x.v[0].xyz, x.v[1].xyz, x.v[2].xyz);
#endif
    } else if (uMode == 5) {
        y.a.x = ggxD(x.v[0].xyz, x.v[0].w);
    } else if (uMode == 6) {
        y.a.x = ggxG1(x.v[0].xyz, x.v[0].w);
        y.a.y = ggxG2(x.v[0].xyz, x.v[1].xyz, x.v[0].w);
    } else if (uMode == 7) {
#ifdef RAYLAB_EXERCISE_SCHLICK
        y.a.xyz = schlickFresnel(x.v[0].xyz, x.v[0].w, x.v[1].xyz, x.v[2].xyz);
#endif
    } else if (uMode == 8) {
        CameraBasis cam = CameraBasis(x.v[0].xyz, x.v[1].xyz, x.v[2].xyz, x.v[3].xyz, x.v[0].w, x.v[1].w);
        Ray r = cameraRayThinLens(cam, x.v[4].xy, x.v[4].zw, x.v[2].w, x.v[3].w);
        y.a.xyz = r.origin;
        y.b.xyz = r.dir;
    } else if (uMode == 9) {
#ifdef RAYLAB_EXERCISE_RUNNING_MEAN
        y.a.xyz = runningMean(x.v[0].xyz, floatBitsToUint(x.v[0].w), x.v[1].xyz, floatBitsToUint(x.v[1].w));
#endif
    }
    outputs[i] = y;
}
