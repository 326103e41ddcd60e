// Scene features the tracer can be specialised for (performance.md: skip what a scene does not
// need). The host (render/shader_variant.cpp) defines RAYLAB_FEATURES_SPECIALISED and exactly the
// features the scene uses, right after #version; absent features compile to nothing. Without
// RAYLAB_FEATURES_SPECIALISED (C++ mirrors, test shaders) every feature is on. Shared by C++ and
// GLSL (preprocessor only).
//   RAYLAB_FEATURE_SPHERES         the scene has spheres
//   RAYLAB_FEATURE_MESHES          the scene has triangle meshes
//   RAYLAB_FEATURE_SMOOTH_NORMALS  some mesh has per-vertex normals
//   RAYLAB_FEATURE_DOF             the camera has a lens (camera.aperture > 0)
//   RAYLAB_FEATURE_TEXTURES        some material has an image texture
//   RAYLAB_TOP_LEVEL_LINEAR        few objects: loop over them instead of the top-level BVH
//   RAYLAB_NEE                     next-event estimation (render.nee)
//   RAYLAB_GENERAL_BSDF            GGX specular and glass (some material has f0 or transmission)
//   RAYLAB_SKY_MAP                 an HDR environment image (sky.type map)
//   RAYLAB_TEXTURE_ROUGHNESS       some material has a roughness texture (with TEXTURES)
//   RAYLAB_TEXTURE_METALLIC        metallic mixed per hit: a metallic texture, or metallic with an
//                                  albedo texture (with TEXTURES)
//   RAYLAB_TEXTURE_EMISSION        some material has an emission texture (with TEXTURES)
//   RAYLAB_TEXTURE_WRAP_MODES      some texture clamps or mirrors instead of repeating (glTF)
//   RAYLAB_STAGE                   render.stage below full (teaching): RAYLAB_STAGE_* below; absent = full
//   RAYLAB_EMISSIVE_TRIANGLES      with RAYLAB_NEE: some mesh emits, its triangles are lights
//   RAYLAB_LIGHT_POWER_SELECTION   with RAYLAB_NEE: lights differ in power, picked by power
#ifndef RAYLAB_FEATURES_GLSL
#define RAYLAB_FEATURES_GLSL
#ifndef RAYLAB_FEATURES_SPECIALISED
#define RAYLAB_FEATURE_SPHERES 1
#define RAYLAB_FEATURE_MESHES 1
#define RAYLAB_FEATURE_SMOOTH_NORMALS 1
#define RAYLAB_FEATURE_DOF 1
#define RAYLAB_FEATURE_TEXTURES 1
#define RAYLAB_NEE 1
#define RAYLAB_GENERAL_BSDF 1
#define RAYLAB_SKY_MAP 1
#define RAYLAB_TEXTURE_ROUGHNESS 1
#define RAYLAB_TEXTURE_METALLIC 1
#define RAYLAB_TEXTURE_EMISSION 1
#define RAYLAB_TEXTURE_WRAP_MODES 1
#define RAYLAB_EMISSIVE_TRIANGLES 1
#define RAYLAB_LIGHT_POWER_SELECTION 1
#endif
// The teaching stages of render.stage (scene.h RenderStage): each adds to the one before.
#define RAYLAB_STAGE_PRIMARY 0    // flat albedo of the first hit
#define RAYLAB_STAGE_EMISSION 1   // + emitters and sky seen directly
#define RAYLAB_STAGE_LAMBERT 2    // + path tracing, every material Lambertian
#define RAYLAB_STAGE_GGX 3        // + the general BSDF (the host also defines RAYLAB_GENERAL_BSDF)
#define RAYLAB_STAGE_TEXTURES 4   // + textures (RAYLAB_FEATURE_TEXTURES)
#define RAYLAB_STAGE_FULL 5       // + depth of field (RAYLAB_FEATURE_DOF)
#ifndef RAYLAB_STAGE
#define RAYLAB_STAGE RAYLAB_STAGE_FULL
#endif
#endif
