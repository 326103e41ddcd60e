#include "render/gpu_scene.h"

#include "io/image_io.h"
#include "render/baked_mesh_transforms.h"
#include "render/camera_relative.h"
#include "render/environment_distribution.h"
#include "render/few_objects.h"
#include "render/light_list.h"
#include "shaders/include/bindings.glsl"
#include "shaders/include/bsdf.glsl"
#include "shaders/include/scene_types.glsl"

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace raylab {
namespace {

// std430 offsets of GpuMaterial (shaders/include/scene_types.glsl): vec4s, then scalars.
static_assert(sizeof(glsl::GpuMaterial) == 96);
static_assert(offsetof(glsl::GpuMaterial, f0Ior) == 32 && offsetof(glsl::GpuMaterial, albedoTexture) == 48);
static_assert(offsetof(glsl::GpuMaterial, emissionTexture) == 64 && offsetof(glsl::GpuMaterial, normalScale) == 72);
static_assert(offsetof(glsl::GpuMaterial, occlusionTexture) == 80);
static_assert(sizeof(glsl::GpuTriangleLight) == 16 * glsl::TRIANGLE_LIGHT_TEXELS);
static_assert(sizeof(glsl::GpuMaterial) == 16 * glsl::MATERIAL_TEXELS && offsetof(glsl::GpuMaterial, emission) == 16);
// The geometry records are vec4s only, so their std430 layout is their C++ layout.
static_assert(sizeof(glsl::GpuBvhNode) == 32 && sizeof(glsl::GpuInstance) == 144 && sizeof(glsl::GpuTriangle) == 64);
static_assert(sizeof(glsl::GpuBvhNode) == 16 * glsl::BVH_NODE_TEXELS && sizeof(glsl::GpuInstance) == 16 * glsl::INSTANCE_TEXELS &&
              sizeof(glsl::GpuTriangle) == 16 * glsl::TRIANGLE_TEXELS);
// std140 offsets of AnalyticLightBlock: vec4s only.
static_assert(sizeof(glsl::GpuAnalyticLight) == 48 && offsetof(glsl::AnalyticLightBlock, lights) == 16);
// std140 offsets of FewObjectsBlock: arrays of vec4s and of a struct of two.
static_assert(sizeof(glsl::GpuSphere) == 32 && offsetof(glsl::FewObjectsBlock, boxMax) == 16 * glsl::FEW_OBJECTS_MAX &&
              offsetof(glsl::FewObjectsBlock, spheres) == 32 * glsl::FEW_OBJECTS_MAX &&
              offsetof(glsl::FewObjectsBlock, triangles) == 64 * glsl::FEW_OBJECTS_MAX);

// geometryBuffers_ in order: top nodes, mesh nodes, instances, triangles, vertices.
constexpr GLuint kGeometryBindings[5] = {BINDING_TOP_NODES, BINDING_MESH_NODES, BINDING_INSTANCES,
                                         BINDING_TRIANGLES, BINDING_VERTICES};

// geometryTexels_ in order; geometryTexels_[i] views geometryBuffers_[i].
constexpr GLuint kGeometryTexelBindings[4] = {BINDING_TOP_NODE_TEXELS, BINDING_MESH_NODE_TEXELS,
                                              BINDING_INSTANCE_TEXELS, BINDING_TRIANGLE_TEXELS};

// A texture-buffer view of a buffer, RGBA32UI (16-byte texels) or R32UI (4-byte ones); `what`
// starts the error when the GL's texture buffers are too small for it. A view sees the buffer's
// data store as of its attachment, so every upload of the buffer attaches again.
void attachTexels(GLuint texture, GLuint buffer, const char* what, GLenum format = GL_RGBA32UI) {
    GLint64 bytes = 0;
    glGetNamedBufferParameteri64v(buffer, GL_BUFFER_SIZE, &bytes);
    const GLint64 texels = bytes / (format == GL_R32UI ? 4 : 16);
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    if (texels > GLint64(maxTexels))
        throw std::runtime_error(std::string(what) + " " + std::to_string(texels) +
                                 " texels in one texture buffer; this GL allows " + std::to_string(maxTexels));
    glTextureBuffer(texture, format, buffer);
}

template <typename T>
void uploadBuffer(GLuint buffer, std::vector<T> data) {
    data.resize(std::max<size_t>(data.size(), 1));   // an empty SSBO binding is not allowed
    glNamedBufferData(buffer, GLsizeiptr(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
}

} // namespace

bool metallicOnGpu(const Material& m) {
    return m.metallicTextureIndex >= 0 ||
           (m.metallic > 0.0f && (m.albedoTextureIndex >= 0 || m.specularTextureIndex >= 0));
}

GpuScene::GpuScene() {
    glCreateBuffers(1, &sphereBuffer_);
    glCreateBuffers(1, &materialBuffer_);
    glCreateBuffers(1, &lightBuffer_);
    glCreateBuffers(1, &envMarginalBuffer_);
    glCreateBuffers(1, &envConditionalBuffer_);
    glCreateBuffers(5, geometryBuffers_);
    glCreateTextures(GL_TEXTURE_BUFFER, 4, geometryTexels_);
    glCreateBuffers(2, textureBuffers_);
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &textureTexels_);
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &materialTexels_);
    glCreateBuffers(1, &triangleLightBuffer_);
    glCreateBuffers(1, &lightAliasBuffer_);
    glCreateBuffers(1, &triangleLightIndexBuffer_);
    glCreateTextures(GL_TEXTURE_BUFFER, 3, lightTexels_);
    glCreateBuffers(1, &analyticLightBuffer_);
    glCreateBuffers(1, &fewObjectsBuffer_);
}

GpuScene::~GpuScene() {
    glDeleteBuffers(1, &sphereBuffer_);
    glDeleteBuffers(1, &materialBuffer_);
    glDeleteBuffers(1, &lightBuffer_);
    glDeleteBuffers(1, &analyticLightBuffer_);
    glDeleteBuffers(1, &fewObjectsBuffer_);
    glDeleteTextures(1, &skyMapTexture_);
    glDeleteBuffers(1, &envMarginalBuffer_);
    glDeleteBuffers(1, &envConditionalBuffer_);
    glDeleteBuffers(5, geometryBuffers_);
    glDeleteTextures(4, geometryTexels_);
    glDeleteBuffers(2, textureBuffers_);
    glDeleteTextures(1, &textureTexels_);
    glDeleteTextures(1, &materialTexels_);
    glDeleteBuffers(1, &triangleLightBuffer_);
    glDeleteBuffers(1, &lightAliasBuffer_);
    glDeleteBuffers(1, &triangleLightIndexBuffer_);
    glDeleteTextures(3, lightTexels_);
}

SceneGeometry& GpuScene::gpuMeshes() {
    return geometry_.meshesInWorld ? relativeMeshes_ : geometry_;
}

void GpuScene::uploadMeshes(const Scene& scene, const glm::dvec3& origin) {
    // Baked transforms (render/baked_mesh_transforms.h): the CPU's geometry in world space, the
    // GPU's relative to the origin, both built from the vertices in double.
    const bool bake = bakesMeshTransforms(scene);
    geometry_ = buildSceneGeometry(bake ? withMeshTransformsBaked(scene) : scene);
    geometry_.meshesInWorld = bake;
    relativeMeshes_ = bake ? buildSceneGeometry(withMeshTransformsBaked(scene, origin)) : SceneGeometry{};
    ++meshBvhBuilds_;
    uploadBuffer(geometryBuffers_[1], gpuMeshes().meshNodes);
    attachGeometryTexels(1);
    uploadBuffer(geometryBuffers_[4], gpuMeshes().vertices);
}

void GpuScene::upload(const Scene& scene, const glm::dvec3& origin) {
    uploadMeshes(scene, origin);
    uploadSkyMap(scene.sky);
    // Textures: all levels of all textures in one texel array; see shaders/include/scene_textures.glsl.
    std::vector<glm::vec4> texels;
    for (const Texture& t : scene.textures)
        for (const MipLevel& l : t.levels) texels.insert(texels.end(), l.texels.begin(), l.texels.end());
    uploadBuffer(textureBuffers_[0], std::move(texels));
    attachTexels(textureTexels_, textureBuffers_[0], "the scene's textures need");
    uploadMaterials(scene);
    uploadTopLevel(scene, origin);   // spheres, instances, top-level BVH and the lights (needs materialRadiance_)
    uploadBuffer(geometryBuffers_[3], gpuMeshes().triangles);
    attachGeometryTexels(3);
}

void GpuScene::attachGeometryTexels(int view) {
    attachTexels(geometryTexels_[view], geometryBuffers_[view], "the scene's geometry needs");
}

void GpuScene::updateMaterials(const Scene& scene, const glm::dvec3& origin) {
    uploadMaterials(scene);
    ++materialUpdates_;
    uploadTopLevel(scene, origin);   // the light list follows the materials' emission
}

void GpuScene::uploadMaterials(const Scene& scene) {
    std::vector<glsl::GpuMaterial> materials;
    for (const Material& m : scene.materials) {
        // Metallic (bsdfWithMetallic) baked here when the base colour is constant; textured ones
        // are mixed per hit (material_textures.glsl).
        const glsl::BsdfParams baked = glsl::bsdfWithMetallic({m.albedo, m.f0, 0.0f, 0.0f, 1.0f},
                                                              metallicOnGpu(m) ? 0.0f : m.metallic);
        const glm::vec3 albedo = baked.albedo, f0 = baked.f0;
        materials.push_back({glm::vec4(albedo, m.roughness), glm::vec4(m.radiance(), m.transmission),
                             glm::vec4(f0, m.ior), unsigned(m.albedoTextureIndex + 1),
                             unsigned(m.normalTextureIndex + 1), unsigned(m.roughnessTextureIndex + 1),
                             unsigned(m.metallicTextureIndex + 1), unsigned(m.emissionTextureIndex + 1),
                             metallicOnGpu(m) ? m.metallic : 0.0f, m.normalScale,
                             unsigned(m.specularTextureIndex + 1), unsigned(m.occlusionTextureIndex + 1),
                             m.occlusionStrength, 0u, 0u});
    }
    materialRadiance_.clear();
    // Emission varying over a texture is not a light for next-event estimation (the light list
    // carries one radiance per light): BSDF samples alone find it, with full weight.
    for (const Material& m : scene.materials)
        materialRadiance_.push_back(lightRadiance(m));
    uploadBuffer(materialBuffer_, std::move(materials));
    attachTexels(materialTexels_, materialBuffer_, "the scene's materials need");   // the buffer was re-specified

    // Per texture where its levels start in the texel array (upload() puts the levels there in
    // this order).
    std::vector<glm::uvec4> info;
    std::size_t firstTexel = 0;
    for (const Texture& t : scene.textures) {
        const unsigned wrap = (unsigned(t.wrapU) << 16u) | (unsigned(t.wrapV) << 24u);
        info.emplace_back(unsigned(firstTexel), unsigned(t.levels[0].width), unsigned(t.levels[0].height),
                          unsigned(t.levels.size()) | wrap);
        for (const MipLevel& l : t.levels) firstTexel += l.texels.size();
    }
    uploadBuffer(textureBuffers_[1], std::move(info));
}

void GpuScene::updateTransforms(const Scene& scene, const glm::dvec3& origin) {
    if (geometry_.meshesInWorld) {
        // The transforms (and the origin) are in the vertices: the few triangles are placed again.
        uploadMeshes(scene, origin);
        uploadBuffer(geometryBuffers_[3], gpuMeshes().triangles);
        attachGeometryTexels(3);
    } else {
        updateTopLevel(geometry_, scene);
    }
    ++topLevelUpdates_;
    uploadTopLevel(scene, origin);
}

void GpuScene::uploadTopLevel(const Scene& scene, const glm::dvec3& origin) {
    // The top level again over the camera-relative scene; the meshes' BVHs, triangles and vertices
    // are in object space, the same for both, and are lent to it for the light list.
    // Baked meshes are already relative to the origin: they are placed by the identity.
    Scene relative = cameraRelative(scene, origin);
    if (geometry_.meshesInWorld)
        for (Mesh& m : relative.meshes) m.transform = Transform{};
    SceneGeometry& meshes = gpuMeshes();
    relativeTop_.meshRoot = meshes.meshRoot;
    relativeTop_.meshBounds = meshes.meshBounds;
    relativeTop_.meshTriangles = meshes.meshTriangles;
    relativeTop_.meshEscapeSides = meshes.meshEscapeSides;
    updateTopLevel(relativeTop_, relative);
    std::swap(relativeTop_.triangles, meshes.triangles);
    std::swap(relativeTop_.vertices, meshes.vertices);
    LightList lights = buildLightList(relative, relativeTop_, materialRadiance_);
    std::swap(relativeTop_.triangles, meshes.triangles);
    std::swap(relativeTop_.vertices, meshes.vertices);

    for (std::size_t k = 0; k < relativeTop_.spheres.size(); ++k) relativeTop_.spheres[k].info.z = lights.sphereLightIndex.at(k);
    sphereCount_ = int(relativeTop_.spheres.size());
    uploadBuffer(sphereBuffer_, relativeTop_.spheres);
    lightCount_ = int(lights.spheres.size());
    triangleLightCount_ = int(lights.triangles.size());
    lightPower_ = std::move(lights.power);
    // Per triangle 1 + its index in the light list (0: no light), so a BSDF ray that hits an
    // emissive triangle finds its light pdf for MIS (integrator.glsl); GpuTriangle's w holds the
    // triangle's own material (glTF).
    uploadBuffer(triangleLightIndexBuffer_, std::move(lights.triangleLightIndex));
    uploadBuffer(lightBuffer_, std::move(lights.spheres));
    uploadBuffer(triangleLightBuffer_, std::move(lights.triangles));
    uploadBuffer(lightAliasBuffer_, std::move(lights.aliasTable));
    attachTexels(lightTexels_[0], triangleLightBuffer_, "the scene's emissive triangles need");
    attachTexels(lightTexels_[1], lightAliasBuffer_, "the scene's lights need");
    attachTexels(lightTexels_[2], triangleLightIndexBuffer_, "the scene's triangles need", GL_R32UI);
    analyticLightCount_ = int(lights.analytic.size());
    glsl::AnalyticLightBlock block{};
    block.info.x = analyticLightCount_;
    std::copy(lights.analytic.begin(), lights.analytic.end(), block.lights);
    glNamedBufferData(analyticLightBuffer_, sizeof block, &block, GL_STATIC_DRAW);
    uploadBuffer(geometryBuffers_[0], relativeTop_.topNodes);
    uploadBuffer(geometryBuffers_[2], relativeTop_.instances);
    const glsl::FewObjectsBlock few = fewObjectsBlock(relativeTop_);
    glNamedBufferData(fewObjectsBuffer_, sizeof few, &few, GL_STATIC_DRAW);
    attachGeometryTexels(0);
    attachGeometryTexels(2);
}

// The sky map as an RGBA32F texture, rows top first as in the file (v = 0 is straight up); a
// 1×1 black texture when the sky is not a map, so the sampler is always complete.
void GpuScene::uploadSkyMap(const Sky& sky) {
    Image image(1, 1);
    if (sky.type == Sky::Type::Map) image = readImage(sky.map);
    skyMapMax_ = 0.0f;
    for (size_t i = 0; i < image.rgba.size(); ++i)
        if (i % 4 != 3) skyMapMax_ = std::max(skyMapMax_, image.rgba[i]);
    glDeleteTextures(1, &skyMapTexture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &skyMapTexture_);
    glTextureStorage2D(skyMapTexture_, 1, GL_RGBA32F, image.width, image.height);
    glTextureSubImage2D(skyMapTexture_, 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, image.rgba.data());
    glTextureParameteri(skyMapTexture_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(skyMapTexture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    // Importance sampling tables (only used for map skies).
    EnvironmentDistribution dist;
    if (sky.type == Sky::Type::Map) dist = EnvironmentDistribution(image);
    skyMapMeanWeight_ = dist.meanWeight();
    uploadBuffer(envMarginalBuffer_, dist.marginalCdf());
    uploadBuffer(envConditionalBuffer_, dist.conditionalCdf());
}

void GpuScene::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_SPHERES, sphereBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_MATERIALS, materialBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_SPHERE_LIGHTS, lightBuffer_);
    glBindTextureUnit(BINDING_SKY_MAP_TEXTURE, skyMapTexture_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_ENV_MARGINAL, envMarginalBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_ENV_CONDITIONAL, envConditionalBuffer_);
    for (int i = 0; i < 5; ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kGeometryBindings[i], geometryBuffers_[i]);
    for (int i = 0; i < 4; ++i) glBindTextureUnit(kGeometryTexelBindings[i], geometryTexels_[i]);
    glBindTextureUnit(BINDING_TEXTURE_TEXELS, textureTexels_);
    glBindTextureUnit(BINDING_MATERIAL_TEXELS, materialTexels_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_TEXTURE_INFO, textureBuffers_[1]);
    glBindTextureUnit(BINDING_TRIANGLE_LIGHT_TEXELS, lightTexels_[0]);
    glBindTextureUnit(BINDING_LIGHT_ALIAS_TEXELS, lightTexels_[1]);
    glBindTextureUnit(BINDING_TRIANGLE_LIGHT_INDEX_TEXELS, lightTexels_[2]);
    glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_ANALYTIC_LIGHTS_UBO, analyticLightBuffer_);
    glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_FEW_OBJECTS_UBO, fewObjectsBuffer_);
}

} // namespace raylab
