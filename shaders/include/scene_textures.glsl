// The host contract for textures (bindings 14–15, render/gpu_scene.cpp) and the lookup of a
// material's albedo texture. GLSL only; the sampling itself is shared (texture.glsl).
#ifndef RAYLAB_SCENE_TEXTURES_GLSL
#define RAYLAB_SCENE_TEXTURES_GLSL

layout(std430, binding = 14) readonly buffer TextureTexelBuffer { vec4 textureTexels[]; };
// [0].x = number of materials M; [1 + m].x = material m's albedo texture + 1 (0 = none), .y its
// normal map + 1;
// [1 + M + k] = texture k (GpuTexture.info: offset, width, height, levels).
layout(std430, binding = 15) readonly buffer TextureInfoBuffer { uvec4 textureInfo[]; };

vec4 texelAt(uint i) { return textureTexels[i]; }

#include "texture.glsl"

// 0 when the material has no albedo texture, else the texture's index + 1.
uint materialAlbedoTexture(uint material) { return textureInfo[1u + material].x; }

uint materialNormalTexture(uint material) { return textureInfo[1u + material].y; }

GpuTexture textureRecord(uint k) { return GpuTexture(textureInfo[1u + textureInfo[0].x + k]); }

#endif
