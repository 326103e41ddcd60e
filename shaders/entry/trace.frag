#version 450 core
// Fragment entry of the path tracer: a full-screen triangle, one fragment per pixel, drawn into
// a framebuffer with no attachments; results go to uAccum by imageStore.
// Defines set by the host: RAYLAB_FEATURES_SPECIALISED and the scene's RAYLAB_FEATURE_SPHERES,
// RAYLAB_FEATURE_MESHES, RAYLAB_FEATURE_SMOOTH_NORMALS, RAYLAB_FEATURE_DOF
// (render/shader_variant.cpp, include/features.glsl); the scene's data arrives in buffers and uniforms.
// Also from the scene: RAYLAB_NEE (render.nee), RAYLAB_GENERAL_BSDF (a material has f0 > 0 or
// transmission > 0), RAYLAB_SKY_MAP (sky.type map); see integrator.glsl.
// With textures: RAYLAB_FEATURE_TEXTURES, RAYLAB_SHOW_MIP_LEVEL (render.show_mip_level) and, per
// kind some material uses, RAYLAB_TEXTURE_ROUGHNESS, RAYLAB_TEXTURE_METALLIC, RAYLAB_TEXTURE_EMISSION,
// RAYLAB_TEXTURE_WRAP_MODES (include/features.glsl, include/material_textures.glsl).
// Optional, tests only: RAYLAB_INJECT_NONFINITE=N (every N-th sample becomes NaN or Inf).
// Optional, debug: RAYLAB_COUNT_TRAVERSAL (boxes and triangles tested, include/scene_geometry.glsl).
// Optional, the pixel path inspector only: RAYLAB_INSPECT_PATHS (records the estimator of one
// pixel into buffers 20 and 21, include/path_record.glsl; src/inspect/path_inspector.h).
#include "../include/path_tracer.glsl"

void main() {
    tracePixelPass(ivec2(gl_FragCoord.xy));
}
