#version 450 core
// Compute entry of the path tracer: one invocation per pixel.
// Defines set by the host: LOCAL_SIZE_X, LOCAL_SIZE_Y (work-group size; llvmpipe runs 8 lanes
// along x, so LOCAL_SIZE_X should be a multiple of 8).
// Optional, set by the host from the scene: RAYLAB_NEE (render.nee), RAYLAB_GENERAL_BSDF (a
// material has f0 > 0 or transmission > 0), RAYLAB_SKY_MAP (sky.type map); see integrator.glsl.
// Optional, tests only: RAYLAB_INJECT_NONFINITE=N (every N-th sample becomes NaN or Inf).
#include "../include/path_tracer.glsl"

layout(local_size_x = LOCAL_SIZE_X, local_size_y = LOCAL_SIZE_Y) in;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= uImageSize.x || pixel.y >= uImageSize.y) return;
    tracePixelPass(pixel);
}
