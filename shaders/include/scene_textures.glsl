// The host contract for textures (render/gpu_scene.cpp). GLSL only; the sampling itself is shared (texture.glsl).
#ifndef RAYLAB_SCENE_TEXTURES_GLSL
#define RAYLAB_SCENE_TEXTURES_GLSL
#include "bindings.glsl"

layout(std430, binding = BINDING_TEXTURE_TEXELS) readonly buffer TextureTexelBuffer { vec4 textureTexels[]; };
// Texture k (GpuTexture.info: offset, width, height, levels and wrap modes); a material names its
// textures in GpuMaterial.
layout(std430, binding = BINDING_TEXTURE_INFO) readonly buffer TextureInfoBuffer { uvec4 textureInfo[]; };

vec4 texelAt(uint i) { return textureTexels[i]; }

#include "texture.glsl"

GpuTexture textureRecord(uint k) { return GpuTexture(textureInfo[k]); }

#endif
