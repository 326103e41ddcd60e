#include "mesh/displacement.h"

#include "mesh/subdivision.h"
#include "mesh/vertex_normals.h"
#include "texture/cpu_texels.h"
#include "shaders/include/texture.glsl"

#include <chrono>

namespace raylab {

void displaceAlongNormals(Mesh& mesh, const std::function<float(std::size_t vertex)>& height) {
    const std::vector<glm::vec3> before =
        mesh.normals.empty() ? vertexNormals(mesh.positions, mesh.triangles) : mesh.normals;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) mesh.positions[i] += before[i] * height(i);
    mesh.normals = vertexNormals(mesh.positions, mesh.triangles);
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        glm::vec3& n = mesh.normals[i];
        if (glm::dot(n, n) == 0.0f) n = glm::dot(before[i], before[i]) > 0.0f ? before[i] : glm::vec3(0.0f, 0.0f, 1.0f);
        else if (glm::dot(n, before[i]) < 0.0f) n = -n;
    }
}

float displacementHeight(const Texture& texture, glm::vec2 uv) {
    const MipLevel& level = texture.levels.at(0);
    glsl::cpuTexels = &level.texels;
    const glsl::GpuTexture t{glm::uvec4(0u, unsigned(level.width), unsigned(level.height), 1u)};
    return glsl::sampleTextureLevel(t, 0, uv).r;
}

void displaceMesh(Mesh& mesh, const Texture& texture) {
    const auto start = std::chrono::steady_clock::now();
    MeshDisplacement d = mesh.displacement;
    d.trianglesBefore = mesh.triangles.size();
    mesh = subdivideMesh(mesh, d.subdivision);
    displaceAlongNormals(mesh, [&](std::size_t i) { return d.scale * displacementHeight(texture, mesh.uvs[i]); });
    d.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    mesh.displacement = std::move(d);
}

} // namespace raylab
