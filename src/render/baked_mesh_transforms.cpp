#include "render/baked_mesh_transforms.h"

#include "render/shader_variant.h"
#include "scene/transform.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace raylab {

bool bakesMeshTransforms(const Scene& scene) {
    if (scene.meshes.empty() || scene.spheres.size() + scene.meshes.size() > kLinearTopLevelMax) return false;
    for (const Mesh& m : scene.meshes)
        if (m.triangles.size() > kSmallMeshMax) return false;
    return true;
}

Scene withMeshTransformsBaked(const Scene& scene, const glm::dvec3& origin) {
    Scene out;
    out.sourcePath = scene.sourcePath;
    out.render = scene.render;
    out.camera = scene.camera;
    out.sky = scene.sky;
    out.ao = scene.ao;
    out.materials = scene.materials;
    out.spheres = scene.spheres;
    out.lights = scene.lights;
    out.meshes = scene.meshes;
    for (Mesh& m : out.meshes) {
        // scene/transform.cpp's T · Rz · Ry · Rx · S in double, as render/camera_relative.cpp moves spheres.
        const Transform& t = m.transform;
        const glm::dmat4 id(1.0);
        const glm::dmat4 toWorld = glm::translate(id, glm::dvec3(t.translation)) *
                                   glm::rotate(id, glm::radians(double(t.rotation.z)), glm::dvec3(0, 0, 1)) *
                                   glm::rotate(id, glm::radians(double(t.rotation.y)), glm::dvec3(0, 1, 0)) *
                                   glm::rotate(id, glm::radians(double(t.rotation.x)), glm::dvec3(1, 0, 0)) *
                                   glm::scale(id, glm::dvec3(t.scale));
        for (glm::vec3& p : m.positions) p = glm::vec3(glm::dvec3(toWorld * glm::dvec4(glm::dvec3(p), 1.0)) - origin);
        if (t == Transform{}) continue;
        const glm::mat3 normalToWorld = glm::transpose(glm::mat3(inverseTransformMatrix(t)));
        for (glm::vec3& n : m.normals) {
            const glm::vec3 w = normalToWorld * n;
            const float length = glm::length(w);
            n = length > 0.0f ? w / length : n;
        }
    }
    for (Mesh& m : out.meshes) m.transform = Transform{};
    return out;
}

} // namespace raylab
