#include "app/camera_control.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace raylab::ui {
namespace {

constexpr float kMaxElevation = 1.5533f;   // 89 degrees

glm::vec3 rotate(glm::vec3 v, glm::vec3 axis, float angle) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), angle, glm::normalize(axis)) * glm::vec4(v, 0.0f));
}

// Applies yaw about `up` then pitch about the right axis to the offset v, clamping elevation.
glm::vec3 yawPitch(glm::vec3 v, glm::vec3 up, float yaw, float pitch) {
    up = glm::normalize(up);
    const float len = glm::length(v);
    glm::vec3 d = rotate(v / len, up, yaw);
    const float elevation = std::asin(std::clamp(glm::dot(d, up), -1.0f, 1.0f));
    const float target = std::clamp(elevation + pitch, -kMaxElevation, kMaxElevation);
    const glm::vec3 right = glm::cross(d, up);
    if (glm::length(right) > 1e-6f) d = rotate(d, right, target - elevation);
    return d * len;
}

} // namespace

void orbitCamera(Camera& camera, float yaw, float pitch) {
    // The eye moves on a sphere around look_at; dragging right turns the scene to the right.
    camera.position = camera.lookAt + yawPitch(camera.position - camera.lookAt, camera.up, -yaw, pitch);
}

void turnCamera(Camera& camera, float yaw, float pitch) {
    camera.lookAt = camera.position + yawPitch(camera.lookAt - camera.position, camera.up, -yaw, pitch);
}

void moveCamera(Camera& camera, float forward, float right, float up) {
    const glm::vec3 f = glm::normalize(camera.lookAt - camera.position);
    const glm::vec3 r = glm::normalize(glm::cross(f, camera.up));
    const glm::vec3 delta = forward * f + right * r + up * glm::normalize(camera.up);
    camera.position += delta;
    camera.lookAt += delta;
}

void dollyCamera(Camera& camera, float factor) {
    const glm::vec3 v = camera.position - camera.lookAt;
    const float len = glm::length(v);
    const float next = std::max(len * factor, 1e-3f);
    camera.position = camera.lookAt + v * (next / len);
}

} // namespace raylab::ui
