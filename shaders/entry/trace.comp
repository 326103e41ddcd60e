#version 450 core
// Compute entry of the path tracer: one invocation per pixel.
// Defines set by the host: LOCAL_SIZE_X, LOCAL_SIZE_Y (work-group size; llvmpipe runs 8 lanes
// along x, so LOCAL_SIZE_X should be a multiple of 8); RAYLAB_FEATURES_SPECIALISED and the scene's
// RAYLAB_FEATURE_SPHERES, RAYLAB_FEATURE_MESHES, RAYLAB_FEATURE_SMOOTH_NORMALS, RAYLAB_FEATURE_DOF
// (render/shader_variant.cpp, include/features.glsl).
// Optional, set by the host from the scene: RAYLAB_NEE (render.nee), RAYLAB_GENERAL_BSDF (a
// material has f0 > 0 or transmission > 0), RAYLAB_SKY_MAP (sky.type map); see integrator.glsl.
// With textures: RAYLAB_FEATURE_TEXTURES, RAYLAB_SHOW_MIP_LEVEL (render.show_mip_level) and, per
// kind some material uses, RAYLAB_TEXTURE_ROUGHNESS, RAYLAB_TEXTURE_METALLIC, RAYLAB_TEXTURE_EMISSION,
// RAYLAB_TEXTURE_WRAP_MODES (include/features.glsl, include/material_textures.glsl).
// Optional, tests only: RAYLAB_INJECT_NONFINITE=N (every N-th sample becomes NaN or Inf).
// Optional, debug: RAYLAB_COUNT_TRAVERSAL (boxes and triangles tested, include/scene_geometry.glsl).
// Optional, the pixel path inspector only: RAYLAB_INSPECT_PATHS (records the estimator of one
// pixel into buffers 20 and 21, include/path_record.glsl; src/inspect/path_inspector.h).
#include "../include/path_tracer.glsl"

layout(local_size_x = LOCAL_SIZE_X, local_size_y = LOCAL_SIZE_Y) in;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= uImageSize.x || pixel.y >= uImageSize.y) return;
    tracePixelPass(pixel);
}
