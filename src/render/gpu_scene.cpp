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
constexpr GLuint kLightBinding = 4;

template <typename T>
void uploadBuffer(GLuint buffer, std::vector<T> data) {
    data.resize(std::max<size_t>(data.size(), 1));   // an empty SSBO binding is not allowed
    glNamedBufferData(buffer, GLsizeiptr(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
}

} // namespace

GpuScene::GpuScene() {
    glCreateBuffers(1, &sphereBuffer_);
    glCreateBuffers(1, &materialBuffer_);
    glCreateBuffers(1, &lightBuffer_);
}

GpuScene::~GpuScene() {
    glDeleteBuffers(1, &sphereBuffer_);
    glDeleteBuffers(1, &materialBuffer_);
    glDeleteBuffers(1, &lightBuffer_);
}

void GpuScene::upload(const Scene& scene) {
    std::vector<glsl::GpuSphere> spheres;
    for (const Sphere& s : scene.spheres)
        spheres.push_back({glm::vec4(s.center, s.radius), glm::uvec4(unsigned(s.material), 0, 0, 0)});
    std::vector<glsl::GpuMaterial> materials;
    for (const Material& m : scene.materials)
        materials.push_back({glm::vec4(m.albedo, m.roughness), glm::vec4(m.radiance(), m.transmission),
                             glm::vec4(m.f0, m.ior)});
    // Emissive spheres, for next-event estimation.
    std::vector<glsl::GpuLight> lights;
    for (const Sphere& s : scene.spheres) {
        const glm::vec3 radiance = scene.materials[size_t(s.material)].radiance();
        if (std::max({radiance.r, radiance.g, radiance.b}) > 0.0f)
            lights.push_back({glm::vec4(s.center, s.radius), glm::vec4(radiance, 0.0f)});
    }
    sphereCount_ = int(spheres.size());
    lightCount_ = int(lights.size());
    uploadBuffer(lightBuffer_, std::move(lights));
    uploadBuffer(sphereBuffer_, std::move(spheres));
    uploadBuffer(materialBuffer_, std::move(materials));
}

void GpuScene::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSphereBinding, sphereBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMaterialBinding, materialBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightBinding, lightBuffer_);
}

} // namespace raylab
