#include "render/shader_variant.h"

#include "render/gpu_scene.h"
#include "render/light_list.h"
#include "render/tracer_defines.h"

#include <algorithm>
#include <string>

namespace raylab {

SceneFeatures sceneFeatures(const Scene& scene) {
    SceneFeatures f;
    f.spheres = !scene.spheres.empty();
    f.meshes = !scene.meshes.empty();
    f.smoothNormals = false;
    for (const Mesh& m : scene.meshes) f.smoothNormals |= !m.normals.empty();
    f.depthOfField = scene.camera.aperture > 0.0f;
    f.textures = !scene.textures.empty();
    f.linearTopLevel = scene.spheres.size() + scene.meshes.size() <= kLinearTopLevelMax;
    f.showMipLevel = f.textures && scene.render.showMipLevel != 0;
    f.nee = scene.render.nee;
    f.generalBsdf = false;
    for (const Material& m : scene.materials)
        f.generalBsdf |= m.transmission > 0.0f || std::max({m.f0.r, m.f0.g, m.f0.b}) > 0.0f || m.metallic > 0.0f;
    f.roughnessTextures = f.metallicTextures = f.emissionTextures = f.textureWrapModes = false;
    for (const Material& m : scene.materials) {
        f.roughnessTextures |= m.roughnessTextureIndex >= 0;
        f.metallicTextures |= metallicOnGpu(m);
        f.emissionTextures |= m.emissionTextureIndex >= 0;
    }
    for (const Texture& t : scene.textures)
        f.textureWrapModes |= t.wrapU != TextureWrap::Repeat || t.wrapV != TextureWrap::Repeat;
    f.skyMap = scene.sky.type == Sky::Type::Map;
    // Teaching stages leave out what comes later: the variant has none of its code.
    f.stage = scene.render.stage;
    if (f.stage < RenderStage::Ggx) f.generalBsdf = false;
    if (f.stage < RenderStage::Textures) f.textures = f.showMipLevel = false;
    if (f.stage < RenderStage::Full) f.depthOfField = false;
    f.lightPowerSelection = f.nee && lightPowersDiffer(scene);
    f.emissiveTriangles = false;
    for (const Mesh& m : scene.meshes) f.emissiveTriangles |= f.nee && meshHasEmissiveTriangle(scene, m);
    return f;
}

SceneFeatures allFeatures() { return SceneFeatures{}; }

ShaderDefines featureDefines(const SceneFeatures& f) {
    ShaderDefines d = {{tracerDefine("RAYLAB_FEATURES_SPECIALISED"), "1"}};
    if (f.spheres) d.emplace_back(tracerDefine("RAYLAB_FEATURE_SPHERES"), "1");
    if (f.meshes) d.emplace_back(tracerDefine("RAYLAB_FEATURE_MESHES"), "1");
    if (f.smoothNormals) d.emplace_back(tracerDefine("RAYLAB_FEATURE_SMOOTH_NORMALS"), "1");
    if (f.depthOfField) d.emplace_back(tracerDefine("RAYLAB_FEATURE_DOF"), "1");
    if (f.textures) d.emplace_back(tracerDefine("RAYLAB_FEATURE_TEXTURES"), "1");
    if (f.linearTopLevel) d.emplace_back(tracerDefine("RAYLAB_TOP_LEVEL_LINEAR"), "1");
    if (f.showMipLevel) d.emplace_back(tracerDefine("RAYLAB_SHOW_MIP_LEVEL"), "1");
    if (f.nee) d.emplace_back(tracerDefine("RAYLAB_NEE"), "1");
    if (f.generalBsdf) d.emplace_back(tracerDefine("RAYLAB_GENERAL_BSDF"), "1");
    if (f.skyMap) d.emplace_back(tracerDefine("RAYLAB_SKY_MAP"), "1");
    if (f.textures && f.roughnessTextures) d.emplace_back(tracerDefine("RAYLAB_TEXTURE_ROUGHNESS"), "1");
    if (f.textures && f.metallicTextures) d.emplace_back(tracerDefine("RAYLAB_TEXTURE_METALLIC"), "1");
    if (f.textures && f.emissionTextures) d.emplace_back(tracerDefine("RAYLAB_TEXTURE_EMISSION"), "1");
    if (f.textures && f.textureWrapModes) d.emplace_back(tracerDefine("RAYLAB_TEXTURE_WRAP_MODES"), "1");
    if (f.stage != RenderStage::Full) d.emplace_back(tracerDefine("RAYLAB_STAGE"), std::to_string(int(f.stage)));
    if (f.emissiveTriangles) d.emplace_back(tracerDefine("RAYLAB_EMISSIVE_TRIANGLES"), "1");
    if (f.lightPowerSelection) d.emplace_back(tracerDefine("RAYLAB_LIGHT_POWER_SELECTION"), "1");
    return d;
}

std::string featureName(const SceneFeatures& f) {
    std::string name;
    auto add = [&name](bool on, const char* part) {
        if (!on) return;
        if (!name.empty()) name += "+";
        name += part;
    };
    add(f.spheres, "spheres");
    add(f.meshes, "meshes");
    add(f.smoothNormals, "smooth");
    add(f.depthOfField, "dof");
    add(f.textures, "textures");
    add(f.linearTopLevel, "few-objects");
    add(f.showMipLevel, "mip-view");
    add(f.nee, "nee");
    add(f.generalBsdf, "ggx+glass");
    add(f.skyMap, "sky-map");
    add(f.textures && f.roughnessTextures, "roughness-tex");
    add(f.textures && f.metallicTextures, "metallic-tex");
    add(f.textures && f.emissionTextures, "emission-tex");
    add(f.textures && f.textureWrapModes, "wrap-modes");
    static const char* const stages[] = {"stage-primary", "stage-emission", "stage-lambert", "stage-ggx", "stage-textures"};
    add(f.stage != RenderStage::Full, stages[std::min(int(f.stage), 4)]);
    add(f.emissiveTriangles, "triangle-lights");
    add(f.lightPowerSelection, "light-power");
    return name.empty() ? "none" : name;
}

const ShaderProgram& ShaderVariantCache::get(const ShaderDefines& defines, Compile compile, const void* context) {
    std::string key;
    for (const auto& [name, value] : defines) key += name + "=" + value + ";";
    auto it = programs_.find(key);
    if (it == programs_.end()) it = programs_.emplace(key, compile(defines, context)).first;
    return it->second;
}

} // namespace raylab
