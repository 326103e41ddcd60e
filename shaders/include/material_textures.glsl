// A material's image textures applied at a hit: albedo, normal map, roughness, metallic and
// emission, each sampled at the ray cone's level of detail (texture.glsl, ray_cone.glsl).
// GLSL only. Each kind is compiled in only when some material of the scene has it:
//   RAYLAB_FEATURE_TEXTURES     albedo and normal maps (and this file at all)
//   RAYLAB_TEXTURE_ROUGHNESS    roughness × the texture's green channel
//   RAYLAB_TEXTURE_METALLIC     metallic (factor × the texture's blue channel) on the GPU
//   RAYLAB_TEXTURE_EMISSION     emitted radiance × the texture's colour
//   RAYLAB_TEXTURE_SPECULAR     f0 × the texture's colour (before the metallic mix)
#ifndef RAYLAB_MATERIAL_TEXTURES_GLSL
#define RAYLAB_MATERIAL_TEXTURES_GLSL
#include "features.glsl"
#include "bsdf.glsl"
#include "scene_intersect.glsl"
#include "scene_textures.glsl"

// Texture k + 1 (0 = none) sampled at the hit, with the level the ray cone of width coneWidth
// (world units at the hit) picks for it.
vec4 sampleHitTexture(uint k1, Hit hit, vec3 rayDir, float coneWidth) {
    GpuTexture tex = textureRecord(k1 - 1u);
    float cosine = dot(hit.normal, rayDir) / length(rayDir);
    return sampleTexture(tex, hit.uv, rayConeLod(tex, hit.lodBase, coneWidth, cosine));
}

// The factor the emission texture puts on the material's emitted radiance (1 without one).
vec3 materialEmissionScale(Hit hit, vec3 rayDir, float coneWidth) {
#if RAYLAB_TEXTURE_EMISSION
    uint k1 = materials[hit.material].emissionTexture;
    if (k1 > 0u) return sampleHitTexture(k1, hit, rayDir, coneWidth).rgb;
#endif
    return vec3(1.0f);
}

// Applies the textures to the BSDF parameters; a normal map bends hit.shadingNormal.
void applyMaterialTextures(inout Hit hit, vec3 rayDir, float coneWidth, inout BsdfParams bsdf) {
    uint albedoTexture = materials[hit.material].albedoTexture;
    if (albedoTexture > 0u) {
        GpuTexture tex = textureRecord(albedoTexture - 1u);
        float cosine = dot(hit.normal, rayDir) / length(rayDir);
        float lod = rayConeLod(tex, hit.lodBase, coneWidth, cosine);
#if RAYLAB_SHOW_MIP_LEVEL
        // Debug view: the level as a colour ramp (0 blue, 4 green, 8+ red).
        bsdf.albedo = clamp(vec3(lod / 4.0f - 1.0f, 1.0f - abs(lod / 4.0f - 1.0f), 1.0f - lod / 4.0f), 0.0f, 1.0f);
#else
        bsdf.albedo *= sampleTexture(tex, hit.uv, lod).rgb;
#endif
    }
#if RAYLAB_TEXTURE_SPECULAR
    uint specularTexture = materials[hit.material].specularTexture;
    if (specularTexture > 0u) bsdf.f0 *= sampleHitTexture(specularTexture, hit, rayDir, coneWidth).rgb;
#endif
#if RAYLAB_TEXTURE_METALLIC
    // The metallic workflow (scenes/FORMAT.md): the textured albedo is the base colour.
    float metallic = materials[hit.material].metallic;
    uint metallicTexture = materials[hit.material].metallicTexture;
    if (metallicTexture > 0u) metallic *= sampleHitTexture(metallicTexture, hit, rayDir, coneWidth).b;
    if (metallic > 0.0f) bsdf = bsdfWithMetallic(bsdf, metallic);
#endif
#if RAYLAB_TEXTURE_ROUGHNESS
    uint roughnessTexture = materials[hit.material].roughnessTexture;
    if (roughnessTexture > 0u) {
        float r = materials[hit.material].albedo.a * sampleHitTexture(roughnessTexture, hit, rayDir, coneWidth).g;
        bsdf.alpha = ggxAlpha(r);
    }
#endif
    uint normalTexture = materials[hit.material].normalTexture;
    if (normalTexture > 0u) {
        // Tangent-space normal map: rgb in [0, 1] encodes (x, y, z) in [-1, 1] in the frame
        // (∂p/∂u, bitangent, shading normal), ∂p/∂u made orthogonal to the normal first; x and y
        // scaled by the material's normal scale (glTF normalTexture.scale).
        vec3 m = 2.0f * sampleHitTexture(normalTexture, hit, rayDir, coneWidth).rgb - 1.0f;
        float s = materials[hit.material].normalScale;
        m = vec3(m.x * s, m.y * s, m.z);
        vec3 t = hit.tangent - dot(hit.tangent, hit.shadingNormal) * hit.shadingNormal;
        if (dot(t, t) > 0.0f && dot(m, m) > 0.0f) {
            t = normalize(t);
            hit.shadingNormal = normalize(m.x * t + m.y * cross(hit.shadingNormal, t) + m.z * hit.shadingNormal);
        }
    }
}

#endif
