// The host contract for textures (render/gpu_scene.cpp). GLSL only; the sampling itself is shared (texture.glsl).
#ifndef RAYLAB_SCENE_TEXTURES_GLSL
#define RAYLAB_SCENE_TEXTURES_GLSL
#include "bindings.glsl"

// Texels through an integer texture buffer, bit-exact like the geometry's (scene_geometry.glsl): on
// llvmpipe a texel fetch gathers eight lanes at once where a storage-buffer load walks them one by
// one, and a bilinear sample reads four texels (bench/mesh_rays.md).
layout(binding = BINDING_TEXTURE_TEXELS) uniform usamplerBuffer textureTexels;
// Texture k (GpuTexture.info: offset, width, height, levels and wrap modes); a material names its
// textures in GpuMaterial.
layout(std430, binding = BINDING_TEXTURE_INFO) readonly buffer TextureInfoBuffer { uvec4 textureInfo[]; };

vec4 texelAt(uint i) { return uintBitsToFloat(texelFetch(textureTexels, int(i))); }

#include "texture.glsl"

GpuTexture textureRecord(uint k) { return GpuTexture(textureInfo[k]); }

#endif
