#include "render/shader_variant.h"

#include "render/light_list.h"

#include <algorithm>

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
        f.generalBsdf |= m.transmission > 0.0f || std::max({m.f0.r, m.f0.g, m.f0.b}) > 0.0f;
    f.skyMap = scene.sky.type == Sky::Type::Map;
    f.lightPowerSelection = f.nee && lightPowersDiffer(scene);
    f.emissiveTriangles = false;
    for (const Mesh& m : scene.meshes) {
        if (m.material < 0 || std::size_t(m.material) >= scene.materials.size()) continue;
        const glm::vec3 L = scene.materials[std::size_t(m.material)].radiance();
        f.emissiveTriangles |= f.nee && !m.triangles.empty() && std::max({L.r, L.g, L.b}) > 0.0f;
    }
    return f;
}

SceneFeatures allFeatures() { return SceneFeatures{}; }

ShaderDefines featureDefines(const SceneFeatures& f) {
    ShaderDefines d = {{"RAYLAB_FEATURES_SPECIALISED", "1"}};
    if (f.spheres) d.emplace_back("RAYLAB_FEATURE_SPHERES", "1");
    if (f.meshes) d.emplace_back("RAYLAB_FEATURE_MESHES", "1");
    if (f.smoothNormals) d.emplace_back("RAYLAB_FEATURE_SMOOTH_NORMALS", "1");
    if (f.depthOfField) d.emplace_back("RAYLAB_FEATURE_DOF", "1");
    if (f.textures) d.emplace_back("RAYLAB_FEATURE_TEXTURES", "1");
    if (f.linearTopLevel) d.emplace_back("RAYLAB_TOP_LEVEL_LINEAR", "1");
    if (f.showMipLevel) d.emplace_back("RAYLAB_SHOW_MIP_LEVEL", "1");
    if (f.nee) d.emplace_back("RAYLAB_NEE", "1");
    if (f.generalBsdf) d.emplace_back("RAYLAB_GENERAL_BSDF", "1");
    if (f.skyMap) d.emplace_back("RAYLAB_SKY_MAP", "1");
    if (f.emissiveTriangles) d.emplace_back("RAYLAB_EMISSIVE_TRIANGLES", "1");
    if (f.lightPowerSelection) d.emplace_back("RAYLAB_LIGHT_POWER_SELECTION", "1");
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
