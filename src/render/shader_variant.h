#pragma once
// Per-scene specialisation of the tracer: the features a scene uses become #defines right after
// #version (shaders/include/features.glsl), so absent features cost nothing at run time; compiled
// variants are cached by their define set. performance.md measured 12–39% lost to a dead branch
// behind a uniform on llvmpipe.
#include "gl/shader_program.h"
#include "scene/scene.h"

#include <map>
#include <string>

namespace raylab {

struct SceneFeatures {
    bool spheres = true;
    bool meshes = true;
    bool smoothNormals = true;
    bool depthOfField = true;
    bool textures = true;
    bool nee = true;             // render.nee: next-event estimation compiled in (RAYLAB_NEE)
    bool generalBsdf = true;     // some material has f0 > 0 or transmission > 0 (RAYLAB_GENERAL_BSDF)
    bool skyMap = true;          // sky.type map (RAYLAB_SKY_MAP)
    bool emissiveTriangles = true;   // with nee: some mesh's material emits (RAYLAB_EMISSIVE_TRIANGLES)
    bool lightPowerSelection = true; // with nee: lights differ in power, pick by power (RAYLAB_LIGHT_POWER_SELECTION)
    bool linearTopLevel = false; // at most kLinearTopLevelMax objects: no top-level BVH
    bool showMipLevel = false;   // debug view (render.show_mip_level), never part of "all features"
    bool roughnessTextures = true;   // some material has a roughness_texture (RAYLAB_TEXTURE_ROUGHNESS)
    bool metallicTextures = true;    // metallic mixed per hit (RAYLAB_TEXTURE_METALLIC, gpu_scene.h)
    bool emissionTextures = true;    // some material has an emission_texture (RAYLAB_TEXTURE_EMISSION)
    bool textureWrapModes = true;    // some texture clamps or mirrors (RAYLAB_TEXTURE_WRAP_MODES)
    RenderStage stage = RenderStage::Full;   // render.stage below full: RAYLAB_STAGE (teaching)
    bool operator==(const SceneFeatures&) const = default;
};

// Up to this many objects the top level is a plain loop (bench/geometry.md measured it faster).
constexpr std::size_t kLinearTopLevelMax = 16;

SceneFeatures sceneFeatures(const Scene& scene);   // what this scene needs
SceneFeatures allFeatures();                       // the unspecialised tracer
// RAYLAB_FEATURES_SPECIALISED plus one RAYLAB_FEATURE_* per feature that is on.
ShaderDefines featureDefines(const SceneFeatures& features);
// "spheres+meshes+dof", "none" when nothing is on.
std::string featureName(const SceneFeatures& features);

// Compiled programs by define set. Needs a current GL context; programs live as long as the cache.
class ShaderVariantCache {
public:
    using Compile = ShaderProgram (*)(const ShaderDefines&, const void* context);
    // The program for `defines`, compiled on first use by compile(defines, context).
    const ShaderProgram& get(const ShaderDefines& defines, Compile compile, const void* context);
    std::size_t size() const { return programs_.size(); }

private:
    std::map<std::string, ShaderProgram> programs_;
};

} // namespace raylab
