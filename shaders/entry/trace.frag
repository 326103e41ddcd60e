#version 450 core
// Fragment entry of the path tracer: a full-screen triangle, one fragment per pixel, drawn into
// a framebuffer with no attachments; results go to uAccum by imageStore.
// Defines set by the host: none (the scene's data arrives in buffers and uniforms).
// Optional, set by the host from the scene: RAYLAB_NEE (render.nee), RAYLAB_GENERAL_BSDF (a
// material has f0 > 0 or transmission > 0), RAYLAB_SKY_MAP (sky.type map); see integrator.glsl.
// Optional, tests only: RAYLAB_INJECT_NONFINITE=N (every N-th sample becomes NaN or Inf).
#include "../include/path_tracer.glsl"

void main() {
    tracePixelPass(ivec2(gl_FragCoord.xy));
}
