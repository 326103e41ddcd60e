#include "render/camera_relative.h"

#include <glm/gtc/matrix_transform.hpp>

namespace raylab {

glm::dvec3 transformPointInDouble(const Transform& t, const glm::dvec3& p) {
    const glm::dmat4 id(1.0);
    const glm::dvec3 deg(t.rotation);
    const glm::dmat4 r = glm::rotate(id, glm::radians(deg.z), glm::dvec3(0, 0, 1)) *
                         glm::rotate(id, glm::radians(deg.y), glm::dvec3(0, 1, 0)) *
                         glm::rotate(id, glm::radians(deg.x), glm::dvec3(1, 0, 0));
    return glm::dvec3(t.translation) + glm::dvec3(r * glm::dvec4(p * glm::dvec3(t.scale), 1.0));
}

Scene withoutTextures(const Scene& scene) {
    Scene out;
    out.sourcePath = scene.sourcePath;
    out.camera = scene.camera;
    out.render = scene.render;
    out.sky = scene.sky;
    out.ao = scene.ao;
    out.materials = scene.materials;
    out.spheres = scene.spheres;
    out.meshes = scene.meshes;
    out.lights = scene.lights;
    return out;
}

glm::vec3 relativePoint(const glm::vec3& world, const glm::dvec3& origin) {
    return glm::vec3(glm::dvec3(world) - origin);
}

Scene cameraRelative(const Scene& scene, const glm::dvec3& origin) {
    Scene out = withoutTextures(scene);
    out.camera.position = relativePoint(scene.camera.position, origin);
    out.camera.lookAt = relativePoint(scene.camera.lookAt, origin);
    for (Sphere& s : out.spheres) {
        s.center = glm::vec3(transformPointInDouble(s.transform, glm::dvec3(s.center)) - origin);
        s.radius *= s.transform.scale.x;
        s.transform = Transform{};
    }
    for (Mesh& m : out.meshes) m.transform.translation = relativePoint(m.transform.translation, origin);
    for (Light& l : out.lights) l.position = relativePoint(l.position, origin);
    return out;
}

bool needsRebase(const Camera& camera, const glm::dvec3& origin) {
    const double view = glm::length(glm::dvec3(camera.lookAt) - glm::dvec3(camera.position));
    return glm::length(glm::dvec3(camera.position) - origin) > kRebaseViews * view;
}

} // namespace raylab
