#include "render/shader_variant.h"

#include "render/baked_mesh_transforms.h"
#include "render/gpu_scene.h"
#include "render/light_list.h"
#include "render/tracer_defines.h"
#include "shaders/include/sampler.glsl"

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
    f.objectCount = f.linearTopLevel ? int(scene.spheres.size() + scene.meshes.size()) : 0;
    f.sphereCount = f.linearTopLevel ? int(scene.spheres.size()) : 0;
    f.smallMeshes = f.meshes;
    for (const Mesh& m : scene.meshes) f.smallMeshes &= m.triangles.size() <= kSmallMeshMax;
    // The GPU scene applies such meshes' transforms to their vertices: all are placed by the identity.
    f.meshesInWorld = bakesMeshTransforms(scene);
    f.showMipLevel = f.textures && scene.render.showMipLevel != 0;
    f.nee = scene.render.nee;
    f.generalBsdf = false;
    for (const Material& m : scene.materials)
        f.generalBsdf |= m.transmission > 0.0f || std::max({m.f0.r, m.f0.g, m.f0.b}) > 0.0f || m.metallic > 0.0f;
    f.roughnessTextures = f.metallicTextures = f.emissionTextures = f.specularTextures = f.textureWrapModes = false;
    for (const Material& m : scene.materials) {
        f.roughnessTextures |= m.roughnessTextureIndex >= 0;
        f.metallicTextures |= metallicOnGpu(m);
        f.emissionTextures |= m.emissionTextureIndex >= 0;
        f.specularTextures |= m.specularTextureIndex >= 0;
    }
    for (const Texture& t : scene.textures)
        f.textureWrapModes |= t.wrapU != TextureWrap::Repeat || t.wrapV != TextureWrap::Repeat;
    f.skyMap = scene.sky.type == Sky::Type::Map;
    // Teaching stages leave out what comes later: the variant has none of its code.
    f.stage = scene.render.stage;
    f.sampler = scene.render.sampler;
    if (f.stage < RenderStage::Ggx) f.generalBsdf = false;
    if (f.stage < RenderStage::Textures) f.textures = f.showMipLevel = false;
    if (f.stage < RenderStage::Full) f.depthOfField = false;
    f.lightPowerSelection = f.nee && lightPowersDiffer(scene) && scene.render.lightSelection == LightSelection::Power;
    f.diffuseSampling = scene.render.diffuseSampling;
    f.ggxSampling = scene.render.ggxSampling;
    f.lightSampling = scene.render.lightSampling;
    f.accel = scene.render.accel;
    f.flatSteps = flatLoopIterationsPerSample(scene, false) > kLoopIterationBudget / 2;
    f.emissiveTriangles = false;
    for (const Mesh& m : scene.meshes) f.emissiveTriangles |= f.nee && meshHasEmissiveTriangle(scene, m);
    f.sphereLights = false;
    for (const Sphere& sp : scene.spheres) f.sphereLights |= f.nee && sphereIsLight(scene, sp);
    f.skyLight = f.nee && skyMayEmit(scene.sky);
    f.analyticLights = !scene.lights.empty();
    f.adaptive = adaptiveInEffect(scene.render);
    f.oneSidedEmitters = false;
    for (const Mesh& m : scene.meshes) f.oneSidedEmitters |= meshHasFrontOnlyTriangle(scene, m);
    return f;
}

SceneFeatures allFeatures() { return SceneFeatures{}; }

namespace {

// A search that steps through every object and each mesh's triangles, per sample: a traced and a
// shadow ray per bounce, or the AO view's rays.
std::uint64_t searchIterationsPerSample(const Scene& scene, bool steps) {
    std::uint64_t perRay = scene.spheres.size();
    for (const Mesh& m : scene.meshes) {
        const std::uint64_t n = m.triangles.size();
        perRay += 1 + (steps ? n / glsl::FLAT_TRIANGLES_PER_STEP + n % glsl::FLAT_TRIANGLES_PER_STEP : n);
    }
    const std::uint64_t rays = std::max<std::uint64_t>(2 * (std::uint64_t(scene.render.maxBounces) + 1),
                                                       std::uint64_t(scene.ao.rays) + 1);
    return perRay * rays;
}

} // namespace

std::uint64_t flatLoopIterationsPerSample(const Scene& scene, bool steps) {
    return scene.render.accel == Accel::Bvh ? 0 : searchIterationsPerSample(scene, steps);
}

std::uint64_t boundedLoopIterationsPerSample(const Scene& scene, const SceneFeatures& f, bool extraDefines) {
    const bool flat = f.accel != Accel::Bvh;
    const bool fewSmall = !extraDefines && f.linearTopLevel && (!f.meshes || f.smallMeshes);
    if (!flat && !fewSmall) return 0;
    const std::uint64_t search = searchIterationsPerSample(scene, flat && f.usesFlatSteps());
    // Numbers drawn: the pixel's and the lens' pairs, then per bounce at most the BSDF direction,
    // the lobe, the light and the roulette.
    const std::uint64_t perNumber = f.sampler == SamplerKind::ZSobol   ? glsl::ZSOBOL_INDEX_BITS / 2
                                  : f.sampler == SamplerKind::Stratified ? 2
                                                                         : 0;
    const std::uint64_t steps = std::uint64_t(scene.render.maxBounces) + 1;
    return search + steps * (1 + scene.lights.size() + 4 * perNumber) + 2 * perNumber;
}

ShaderDefines featureDefines(const SceneFeatures& f) {
    ShaderDefines d = {{tracerDefine("RAYLAB_FEATURES_SPECIALISED"), "1"}};
#define RL_FEATURE_DEFINE(def, field, needs, name) \
    d.emplace_back(tracerDefine(#def), f.field && f.needs ? "1" : "0");
    RAYLAB_FEATURE_LIST(RL_FEATURE_DEFINE)
#undef RL_FEATURE_DEFINE
    d.emplace_back(tracerDefine("RAYLAB_STAGE"), std::to_string(int(f.stage)));
    d.emplace_back(tracerDefine("RAYLAB_SAMPLER"), std::to_string(int(f.sampler)));
    d.emplace_back(tracerDefine("RAYLAB_DIFFUSE_SAMPLING"), std::to_string(int(f.diffuseSampling)));
    d.emplace_back(tracerDefine("RAYLAB_GGX_SAMPLING"), std::to_string(int(f.ggxSampling)));
    d.emplace_back(tracerDefine("RAYLAB_LIGHT_SAMPLING"), std::to_string(int(f.lightSampling)));
    d.emplace_back(tracerDefine("RAYLAB_ACCEL"), std::to_string(int(f.accel)));
    d.emplace_back(tracerDefine("RAYLAB_FLAT_STEPS"), f.usesFlatSteps() ? "1" : "0");
    d.emplace_back(tracerDefine("RAYLAB_OBJECT_COUNT"), std::to_string(f.objectCount));
    d.emplace_back(tracerDefine("RAYLAB_SPHERE_COUNT"), std::to_string(f.sphereCount));
    return d;
}

std::string featureName(const SceneFeatures& f) {
    std::string name;
    auto add = [&name](bool on, const char* part) {
        if (!on) return;
        if (!name.empty()) name += "+";
        name += part;
    };
#define RL_FEATURE_NAME(def, field, needs, name) add(f.field && f.needs, name);
    RAYLAB_FEATURE_LIST(RL_FEATURE_NAME)
#undef RL_FEATURE_NAME
    static const char* const stages[] = {"stage-primary", "stage-emission", "stage-lambert", "stage-ggx", "stage-textures"};
    add(f.stage != RenderStage::Full, stages[std::min(int(f.stage), 4)]);
    add(f.sampler == SamplerKind::Stratified, "stratified");
    add(f.sampler == SamplerKind::Sobol, "sobol");
    add(f.sampler == SamplerKind::ZSobol, "zsobol");
    add(f.diffuseSampling == DiffuseSampling::Uniform, "diffuse-uniform");
    add(f.ggxSampling == GgxSampling::DCos, "ggx-d-cos");
    add(f.lightSampling == LightSampling::Area, "light-area");
    add(f.accel == Accel::Boxes, "accel-boxes");
    add(f.accel == Accel::None, "accel-none");
    add(f.usesFlatSteps(), "flat-steps");
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
