// GPU-side scene records, laid out for std430 buffers and identical in C++: vec4 / uvec4 members,
// or scalars in groups of four after them, so both languages agree on every offset
// (src/render/gpu_scene.cpp static_asserts them).
#ifndef RAYLAB_SCENE_TYPES_GLSL
#define RAYLAB_SCENE_TYPES_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

struct GpuSphere {
    vec4 centerRadius;   // xyz centre, w radius
    uvec4 info;          // x material index; y its instance (top-level order); z 1 + its index
                         // among the sphere lights, 0 for none (the GPU scene's); w unused
};

struct GpuMaterial {
    vec4 albedo;     // rgb diffuse reflectance, a perceptual roughness
    vec4 emission;   // rgb emitted radiance (colour × strength), a transmission
    vec4 f0Ior;      // rgb specular reflectance at normal incidence, a index of refraction
    // Image textures (material_textures.glsl): each the texture's index + 1, 0 = none.
    uint albedoTexture;
    uint normalTexture;
    uint roughnessTexture;     // roughness × the texture's green channel
    uint metallicTexture;      // metallic × the texture's blue channel
    uint emissionTexture;      // emitted radiance × the texture's colour
    float metallic;            // mixed per hit (render/gpu_scene.h metallicOnGpu), else 0: baked in
    float normalScale;         // normal map x and y scale (glTF normalTexture.scale)
    uint specularTexture;      // f0 × the texture's colour
    uint occlusionTexture;     // baked ambient occlusion in red, read by the baked-ao debug view only
    float occlusionStrength;   // occlusion = 1 + strength × (texel − 1)
    uint unused0;
    uint unused1;
};
const uint MATERIAL_TEXELS = 6u;   // RGBA32UI texels a material record spans

// An emissive sphere, for next-event estimation.
struct GpuLight {
    vec4 centerRadius;   // xyz centre, w radius
    vec4 radiance;       // rgb emitted radiance, a unused
};

// An emissive triangle in world space, for next-event estimation (render/light_list.cpp). It
// emits on both faces, as a BSDF ray that hits it scores it (integrator.glsl), unless its mesh
// says emission_sides front.
struct GpuTriangleLight {
    vec4 p0Area;     // xyz first vertex, w area
    vec4 p1;         // xyz second vertex, w unused
    vec4 p2;         // xyz third vertex, w unused
    vec4 radiance;   // rgb emitted radiance, a 1 = only the (p1 − p0) × (p2 − p0) side emits
};
const uint TRIANGLE_LIGHT_TEXELS = 4u;   // RGBA32UI texels a triangle light's record spans

// Flag in the per-triangle light index (scene_data.glsl triangleLightIndexAt): the triangle emits
// on its front (e01 × e02) side only.
const uint TRIANGLE_FRONT_ONLY = 0x80000000u;

RL_NAMESPACE_END
#endif
