#include "render/gpu_scene.h"

#include "shaders/include/scene_types.glsl"

#include <glad/gl.h>

#include <algorithm>
#include <vector>

namespace raylab {
namespace {

// Binding points; keep in step with shaders/include/scene_data.glsl.
constexpr GLuint kSphereBinding = 1;
constexpr GLuint kMaterialBinding = 2;
constexpr GLuint kFirstGeometryBinding = 8;   // 8–12, see shaders/include/scene_geometry.glsl

template <typename T>
void uploadBuffer(GLuint buffer, std::vector<T> data) {
    data.resize(std::max<size_t>(data.size(), 1));   // an empty SSBO binding is not allowed
    glNamedBufferData(buffer, GLsizeiptr(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
}

} // namespace

GpuScene::GpuScene() {
    glCreateBuffers(1, &sphereBuffer_);
    glCreateBuffers(1, &materialBuffer_);
    glCreateBuffers(5, geometryBuffers_);
    glCreateBuffers(2, textureBuffers_);
}

GpuScene::~GpuScene() {
    glDeleteBuffers(1, &sphereBuffer_);
    glDeleteBuffers(1, &materialBuffer_);
    glDeleteBuffers(5, geometryBuffers_);
    glDeleteBuffers(2, textureBuffers_);
}

void GpuScene::upload(const Scene& scene) {
    geometry_ = buildSceneGeometry(scene);
    uploadBuffer(geometryBuffers_[1], geometry_.meshNodes);
    uploadBuffer(geometryBuffers_[3], geometry_.triangles);
    uploadBuffer(geometryBuffers_[4], geometry_.vertices);
    uploadTopLevel();
    std::vector<glsl::GpuMaterial> materials;
    for (const Material& m : scene.materials)
        materials.push_back({glm::vec4(m.albedo, 0.0f), glm::vec4(m.radiance(), 0.0f)});
    uploadBuffer(materialBuffer_, std::move(materials));

    // Textures: all levels of all textures in one texel array; see shaders/include/scene_textures.glsl.
    std::vector<glm::vec4> texels;
    std::vector<glm::uvec4> info;
    info.emplace_back(unsigned(scene.materials.size()), 0u, 0u, 0u);
    for (const Material& m : scene.materials)
        info.emplace_back(unsigned(m.albedoTextureIndex + 1), unsigned(m.normalTextureIndex + 1), 0u, 0u);
    for (const Texture& t : scene.textures) {
        info.emplace_back(unsigned(texels.size()), unsigned(t.levels[0].width), unsigned(t.levels[0].height),
                          unsigned(t.levels.size()));
        for (const MipLevel& l : t.levels) texels.insert(texels.end(), l.texels.begin(), l.texels.end());
    }
    uploadBuffer(textureBuffers_[0], std::move(texels));
    uploadBuffer(textureBuffers_[1], std::move(info));
}

void GpuScene::updateTransforms(const Scene& scene) {
    updateTopLevel(geometry_, scene);
    uploadTopLevel();
}

void GpuScene::uploadTopLevel() {
    sphereCount_ = int(geometry_.spheres.size());
    uploadBuffer(sphereBuffer_, geometry_.spheres);
    uploadBuffer(geometryBuffers_[0], geometry_.topNodes);
    uploadBuffer(geometryBuffers_[2], geometry_.instances);
}

void GpuScene::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSphereBinding, sphereBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMaterialBinding, materialBuffer_);
    for (GLuint i = 0; i < 5; ++i)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFirstGeometryBinding + i, geometryBuffers_[i]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 14, textureBuffers_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 15, textureBuffers_[1]);
}

} // namespace raylab
