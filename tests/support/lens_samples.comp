#version 450 core
// Test entry point: ray origins of the tracer's thin-lens camera (shaders/include/camera.glsl,
// cameraRayThinLens: the lens disk by the concentric map), drawn as path_tracer.glsl draws them
// (a pixel jitter, then the lens sample, from one stream per sample), in lens coordinates
// divided by the lens radius. One invocation per sample. Host: tests/support/gpu_lens.h.
// Defines set by the host: none.
#include "../../shaders/include/bindings.glsl"
#include "../../shaders/include/camera.glsl"
#include "../../shaders/include/random.glsl"

layout(local_size_x = 64) in;

// xy: lens position / radius; z: the origin's component along the view (0 on the lens plane);
// w: the ray direction's length minus 1.
layout(std430, binding = BINDING_TEST_OUTPUT) writeonly buffer LensSampleBuffer { vec4 lensSamples[]; };
uniform uint uCount;
uniform uint uSeed;
uniform vec3 uPosition;
uniform vec3 uLookAt;
uniform float uLensRadius;
uniform float uFocusDistance;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) return;
    CameraBasis cam = cameraBasis(uPosition, uLookAt, vec3(0.0, 1.0, 0.0), 40.0, 1.5);
    Rng rng = rngCreate(uvec2(i % 1024u, i / 1024u), 0u, uSeed);
    vec2 ndc = 2.0 * rngNext2(rng) - 1.0;
    Ray r = cameraRayThinLens(cam, ndc, rngNext2(rng), uLensRadius, uFocusDistance);
    vec3 d = r.origin - cam.origin;
    lensSamples[i] = vec4(dot(d, cam.right) / uLensRadius, dot(d, cam.up) / uLensRadius, dot(d, cam.forward),
                          length(r.dir) - 1.0);
}
