#version 450 core
// Test harness: draws samples with the real GLSL sampling code and stores them for χ² tests on
// the CPU (tests/shaders/gpu_sampling_test.cpp). One invocation per sample.
// Defines set by the host: none. Uniforms below.
#include "random.glsl"
#include "sampling.glsl"
#include "bsdf.glsl"

layout(local_size_x = 64) in;

struct SampleRecord {
    vec4 wiPdf;         // xyz direction (local frame), w pdf
    vec4 weightLobe;    // xyz weight, w lobe (+ 8 when delta)
};
layout(std430, binding = 0) writeonly buffer Samples { SampleRecord samples[]; };

uniform uint uCount;
uniform uint uSeed;
uniform int uMode;          // 0: cosine hemisphere, 1: bsdfSample
uniform vec3 uWo;           // local frame
uniform vec3 uAlbedo;
uniform vec3 uF0;
uniform float uAlpha;
uniform float uTransmission;
uniform float uIor;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) return;
    Rng rng = rngCreate(uvec2(i, 0u), 0u, uSeed);
    vec2 u = rngNext2(rng);
    float uLobe = rngNextFloat(rng);
    if (uMode == 0) {
        vec3 w = sampleCosineHemisphere(u);
        samples[i] = SampleRecord(vec4(w, pdfCosineHemisphere(w.z)), vec4(1.0, 1.0, 1.0, float(LOBE_DIFFUSE)));
        return;
    }
    BsdfParams m = BsdfParams(uAlbedo, uF0, uAlpha, uTransmission, uIor);
    BsdfSample s = bsdfSample(m, uWo, vec3(u.x, u.y, uLobe));
    samples[i] = SampleRecord(vec4(s.wi, s.pdf), vec4(s.weight, float(s.lobe + (s.delta ? 8 : 0))));
}
