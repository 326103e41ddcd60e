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

template <typename T>
void uploadBuffer(GLuint buffer, std::vector<T> data) {
    data.resize(std::max<size_t>(data.size(), 1));   // an empty SSBO binding is not allowed
    glNamedBufferData(buffer, GLsizeiptr(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
}

} // namespace

GpuScene::GpuScene() {
    glCreateBuffers(1, &sphereBuffer_);
    glCreateBuffers(1, &materialBuffer_);
}

GpuScene::~GpuScene() {
    glDeleteBuffers(1, &sphereBuffer_);
    glDeleteBuffers(1, &materialBuffer_);
}

void GpuScene::upload(const Scene& scene) {
    std::vector<glsl::GpuSphere> spheres;
    for (const Sphere& s : scene.spheres)
        spheres.push_back({glm::vec4(s.center, s.radius), glm::uvec4(unsigned(s.material), 0, 0, 0)});
    std::vector<glsl::GpuMaterial> materials;
    for (const Material& m : scene.materials)
        materials.push_back({glm::vec4(m.albedo, 0.0f), glm::vec4(m.radiance(), 0.0f)});
    sphereCount_ = int(spheres.size());
    uploadBuffer(sphereBuffer_, std::move(spheres));
    uploadBuffer(materialBuffer_, std::move(materials));
}

void GpuScene::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSphereBinding, sphereBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMaterialBinding, materialBuffer_);
}

} // namespace raylab
