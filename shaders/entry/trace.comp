#version 450 core
// Compute entry of the path tracer: one invocation per pixel. The scene's data arrives in buffers
// and uniforms.
// Defines set by the host: the scene's features, every one 0 or 1 (include/features.glsl), and
// the optional debug and test defines; the one list is src/render/tracer_defines.h.
// LOCAL_SIZE_X and LOCAL_SIZE_Y give the work-group size (llvmpipe runs 8 lanes along x, so
// LOCAL_SIZE_X should be a multiple of 8).
#include "../include/path_tracer.glsl"

layout(local_size_x = LOCAL_SIZE_X, local_size_y = LOCAL_SIZE_Y) in;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= params.imageSize.x || pixel.y >= params.imageSize.y) return;
    tracePixelPass(pixel);
}
