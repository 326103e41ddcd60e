#version 450 core
// Sampler harness: draws samples with the real GLSL sampling code and stores them for χ² tests on
// the CPU: the test suite's (tests/shaders/gpu_sampling_test.cpp), the viewer's self-test and its BRDF explorer
// (host: src/selftest/gpu_sampler.cpp).
// One invocation per sample.
// Defines set by the host: every feature on (render/shader_variant.h allFeatures). Uniforms below; the output buffer has a binding point of its own so
// that the scene's buffers (the sky map tables) can stay bound.
#include "bindings.glsl"
#include "random.glsl"
#include "sampling.glsl"
#include "bsdf.glsl"
#include "light_sampling.glsl"
#include "environment_sampling.glsl"   // the sky map and its tables, bound by GpuScene
#include "triangle_light.glsl"
#include "light_selection.glsl"         // the light alias table, bound by GpuScene

layout(local_size_x = 64) in;

struct SampleRecord {
    vec4 wiPdf;         // xyz direction (local frame), w pdf
    vec4 weightLobe;    // xyz weight, w lobe (+ 8 when delta)
};
layout(std430, binding = BINDING_BSDF_SAMPLES) writeonly buffer Samples { SampleRecord samples[]; };

uniform uint uCount;        // the seed and light counts come from the tracer's params block
uniform int uMode;          // 0: cosine hemisphere, 1: bsdfSample, 2: sphere cone, 3: sky map,
                            // 4: triangle light, 5: light selection
uniform vec3 uTriangle0;    // mode 4: the triangle, seen from the origin
uniform vec3 uTriangle1;
uniform vec3 uTriangle2;
uniform vec3 uSphereCenter; // mode 2: the sphere, seen from the origin
uniform float uSphereRadius;
uniform vec3 uWo;           // local frame
uniform vec3 uAlbedo;
uniform vec3 uF0;
uniform float uAlpha;
uniform float uTransmission;
uniform float uIor;
uniform int uDiffuseSampling;   // mode 1: render.diffuse_sampling and render.ggx_sampling
uniform int uGgxSampling;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) return;
    Rng rng = rngCreate(uvec2(i, 0u), 0u, params.seed);
    vec2 u = rngNext2(rng);
    float uLobe = rngNextFloat(rng);
    if (uMode == 0) {
        vec3 w = sampleCosineHemisphere(u);
        samples[i] = SampleRecord(vec4(w, pdfCosineHemisphere(w.z)), vec4(1.0, 1.0, 1.0, float(LOBE_DIFFUSE)));
        return;
    }
    if (uMode == 2) {
        vec3 w = sphereConeSample(vec3(0.0), uSphereCenter, uSphereRadius, u);
        samples[i] = SampleRecord(vec4(w, sphereConePdf(vec3(0.0), uSphereCenter, uSphereRadius)), vec4(0.0));
        return;
    }
    if (uMode == 3) {
        float pdf;
        vec2 uv;
        vec3 w = sampleEnvironment(u, pdf, uv);
        samples[i] = SampleRecord(vec4(w, pdf), vec4(uv, environmentPdf(w), 0.0));
        return;
    }
    if (uMode == 4) {
        // As the integrator does it (sampleTriangleLight): the direction, its solid-angle pdf, and
        // the pdf that a BSDF sample meeting the same point would be weighed with (MIS).
        vec3 e = cross(uTriangle1 - uTriangle0, uTriangle2 - uTriangle0);
        float area = 0.5 * length(e);
        vec3 w, q;
        float pdf = sampleTriangleLight(vec3(0.0), uTriangle0, uTriangle1, uTriangle2, area, u, w, q);
        float hitPdf = triangleLightDirectionPdf(vec3(0.0), uTriangle0, uTriangle1, uTriangle2, area, dot(q, q),
                                                 dot(normalize(e), w));
        samples[i] = SampleRecord(vec4(w, pdf), vec4(hitPdf, q));
        return;
    }
    if (uMode == 5) {
        // x: the light picked (-1 the sky), y: its probability, z: boundedLightPmf of it, w: the number
        // that picked it, rescaled within the pick.
        float pmf;
        Sampler pick = samplerCreate(uvec2(i, 1u), 0u, params.seed, 1u);
        float u = sample1D(pick, 0u);
        int k = selectLight(pick, u, pmf);
        samples[i] = SampleRecord(vec4(float(k), pmf, k >= 0 ? boundedLightPmf(k) : 0.0, u), vec4(0.0));
        return;
    }
    BsdfParams m = BsdfParams(uAlbedo, uF0, uAlpha, uTransmission, uIor, uDiffuseSampling, uGgxSampling);
    BsdfSample s = bsdfSample(m, uWo, vec3(u.x, u.y, uLobe));
    samples[i] = SampleRecord(vec4(s.wi, s.pdf), vec4(s.weight, float(s.lobe + (s.delta ? 8 : 0))));
}
