#include "scene/transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace raylab {
namespace {

glm::mat4 rotationXyz(glm::vec3 degrees) {
    const glm::mat4 id(1.0f);
    const glm::mat4 rx = glm::rotate(id, glm::radians(degrees.x), glm::vec3(1, 0, 0));
    const glm::mat4 ry = glm::rotate(id, glm::radians(degrees.y), glm::vec3(0, 1, 0));
    const glm::mat4 rz = glm::rotate(id, glm::radians(degrees.z), glm::vec3(0, 0, 1));
    return rz * ry * rx;
}

} // namespace

glm::mat4 transformMatrix(const Transform& t) {
    return glm::translate(glm::mat4(1.0f), t.translation) * rotationXyz(t.rotation) *
           glm::scale(glm::mat4(1.0f), t.scale);
}

glm::mat4 inverseTransformMatrix(const Transform& t) {
    // (T R S)^-1 = S^-1 R^T T^-1; a rotation's inverse is its transpose.
    return glm::scale(glm::mat4(1.0f), 1.0f / t.scale) * glm::transpose(rotationXyz(t.rotation)) *
           glm::translate(glm::mat4(1.0f), -t.translation);
}

Sphere worldSphere(const Sphere& s) {
    Sphere w = s;
    w.center = glm::vec3(transformMatrix(s.transform) * glm::vec4(s.center, 1.0f));
    w.radius = s.radius * s.transform.scale.x;
    w.transform = Transform{};
    return w;
}

} // namespace raylab
