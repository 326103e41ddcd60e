#include "render/baked_mesh_transforms.h"

#include "render/camera_relative.h"
#include "render/shader_variant.h"
#include "scene/transform.h"

#include <glm/glm.hpp>

namespace raylab {

bool bakesMeshTransforms(const Scene& scene) {
    if (scene.meshes.empty() || scene.spheres.size() + scene.meshes.size() > kLinearTopLevelMax) return false;
    for (const Mesh& m : scene.meshes)
        if (m.triangles.size() > kSmallMeshMax) return false;
    return true;
}

Scene withMeshTransformsBaked(const Scene& scene, const glm::dvec3& origin) {
    Scene out = withoutTextures(scene);
    for (Mesh& m : out.meshes) {
        const Transform& t = m.transform;
        for (glm::vec3& p : m.positions) p = glm::vec3(transformPointInDouble(t, glm::dvec3(p)) - origin);
        if (t == Transform{}) continue;
        const glm::mat3 normalToWorld = glm::transpose(glm::mat3(inverseTransformMatrix(t)));
        for (glm::vec3& n : m.normals) {
            const glm::vec3 w = normalToWorld * n;
            const float length = glm::length(w);
            n = length > 0.0f ? w / length : n;
        }
        m.transform = Transform{};
    }
    return out;
}

} // namespace raylab
