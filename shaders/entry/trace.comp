#version 450 core
// Compute entry of the path tracer: one invocation per pixel. The scene's data arrives in buffers
// and uniforms.
// Defines set by the host (render/path_tracer.cpp): LOCAL_SIZE_X, LOCAL_SIZE_Y (work-group size;
// llvmpipe runs 8 lanes along x, so LOCAL_SIZE_X should be a multiple of 8).
// From the scene (render/shader_variant.cpp featureDefines; include/features.glsl lists them):
// RAYLAB_FEATURES_SPECIALISED and RAYLAB_FEATURE_SPHERES, RAYLAB_FEATURE_MESHES,
// RAYLAB_FEATURE_SMOOTH_NORMALS, RAYLAB_FEATURE_DOF, RAYLAB_FEATURE_TEXTURES; RAYLAB_TOP_LEVEL_LINEAR
// (few objects: no top-level BVH); RAYLAB_NEE (render.nee), RAYLAB_GENERAL_BSDF (a material has
// f0 > 0 or transmission > 0), RAYLAB_SKY_MAP (sky.type map), RAYLAB_EMISSIVE_TRIANGLES and
// RAYLAB_LIGHT_POWER_SELECTION (with NEE: emissive meshes, lights of unequal power; see
// integrator.glsl); RAYLAB_STAGE=N (render.stage below full, the teaching stages).
// With textures: RAYLAB_SHOW_MIP_LEVEL (render.show_mip_level) and, per kind some material uses,
// RAYLAB_TEXTURE_ROUGHNESS, RAYLAB_TEXTURE_METALLIC, RAYLAB_TEXTURE_EMISSION,
// RAYLAB_TEXTURE_WRAP_MODES (include/material_textures.glsl).
// Optional, the viewer's and raylab-render's debug variants: RAYLAB_DEBUG_VIEWS (debug views),
// RAYLAB_DEBUG_MOMENTS (per-pixel moments for the noise and NaN views), RAYLAB_COUNT_TRAVERSAL
// (boxes and triangles tested, include/scene_geometry.glsl).
// Optional, the pixel path inspector only: RAYLAB_INSPECT_PATHS (records the estimator of one
// pixel into buffers 20 and 21, include/path_record.glsl; src/inspect/path_inspector.h).
// Optional, tests only: RAYLAB_INJECT_NONFINITE=N (every N-th sample becomes NaN or Inf).
// The one list of these names: src/render/tracer_defines.h.
#include "../include/path_tracer.glsl"

layout(local_size_x = LOCAL_SIZE_X, local_size_y = LOCAL_SIZE_Y) in;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= params.imageSize.x || pixel.y >= params.imageSize.y) return;
    tracePixelPass(pixel);
}
