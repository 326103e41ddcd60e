#version 450 core
// Test entry point: the points sample2D (shaders/include/sampler.glsl) gives one pixel's samples in
// one dimension pair, every earlier dimension drawn once before it (independent takes its numbers
// in call order). One invocation per sample. Host: tests/inspect/sample_points_test.cpp.
// Defines set by the host: featureDefines() with the sampler under test (RAYLAB_SAMPLER).
#include "../../shaders/include/bindings.glsl"
#include "../../shaders/include/sampler.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = BINDING_TEST_OUTPUT) writeonly buffer SamplePointBuffer { vec2 points[]; };
uniform uint uCount;
uniform uint uFirst;
uniform ivec2 uPixel;
uniform uint uSeed;
uniform uint uSpp;
uniform uint uDim;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) return;
    Sampler smp = samplerCreate(uvec2(uPixel), uFirst + i, uSeed, uSpp);
    for (uint d = 0u; d < uDim; ++d) sample1D(smp, d);
    points[i] = sample2D(smp, uDim);
}
