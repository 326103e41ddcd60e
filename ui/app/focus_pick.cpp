#include "app/focus_pick.h"

#include "accel/cpu_traversal.h"
#include "shaders/include/camera.glsl"

namespace raylab::ui {

std::optional<float> focusDistanceAt(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                                     ImagePoint point) {
    const Camera& c = scene.camera;
    const glsl::CameraBasis b = glsl::cameraBasis(c.position, c.lookAt, c.up, c.fovY, float(width) / float(height));
    // Image y runs down, ndc y up (as view_geometry.cpp).
    const glm::vec2 ndc(point.x / float(width) * 2.0f - 1.0f, 1.0f - point.y / float(height) * 2.0f);
    const glsl::Ray ray = glsl::cameraRay(b, ndc);
    glsl::cpuTraversal.geometry = &geometry;
    glsl::TraceRecord rec;
    const bool hit = glsl::traceScene(ray, glsl::FLOAT_MAX, false, rec);
    glsl::cpuTraversal.geometry = nullptr;
    if (!hit) return std::nullopt;
    return rec.t * glm::dot(ray.dir, b.forward);   // |dir| = 1: t is the distance along the ray
}

} // namespace raylab::ui
