// The host contract for textures (render/gpu_scene.cpp) and the lookup of a
// material's textures. GLSL only; the sampling itself is shared (texture.glsl).
#ifndef RAYLAB_SCENE_TEXTURES_GLSL
#define RAYLAB_SCENE_TEXTURES_GLSL
#include "bindings.glsl"

layout(std430, binding = BINDING_TEXTURE_TEXELS) readonly buffer TextureTexelBuffer { vec4 textureTexels[]; };
// [0].x = number of materials M; two records per material m:
//   [1 + 2m]  = albedo, normal, roughness, metallic texture, each its index + 1 (0 = none);
//   [2 + 2m]  = x emission texture + 1, y metallic factor, z normal scale (float bits);
// [1 + 2M + k] = texture k (GpuTexture.info: offset, width, height, levels and wrap modes).
layout(std430, binding = BINDING_TEXTURE_INFO) readonly buffer TextureInfoBuffer { uvec4 textureInfo[]; };

vec4 texelAt(uint i) { return textureTexels[i]; }

#include "texture.glsl"

// 0 when the material has no such texture, else the texture's index + 1.
uint materialAlbedoTexture(uint material) { return textureInfo[1u + 2u * material].x; }
uint materialNormalTexture(uint material) { return textureInfo[1u + 2u * material].y; }
uint materialRoughnessTexture(uint material) { return textureInfo[1u + 2u * material].z; }
uint materialMetallicTexture(uint material) { return textureInfo[1u + 2u * material].w; }
uint materialEmissionTexture(uint material) { return textureInfo[2u + 2u * material].x; }
float materialMetallic(uint material) { return uintBitsToFloat(textureInfo[2u + 2u * material].y); }
float materialNormalScale(uint material) { return uintBitsToFloat(textureInfo[2u + 2u * material].z); }

GpuTexture textureRecord(uint k) { return GpuTexture(textureInfo[1u + 2u * textureInfo[0].x + k]); }

#endif
