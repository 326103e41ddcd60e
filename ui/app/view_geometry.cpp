#include "app/view_geometry.h"

#include "accel/cpu_traversal.h"
#include "app/scene_object.h"
#include "scene/transform.h"
#include "shaders/include/camera.glsl"


namespace raylab::ui {
namespace {

glsl::CameraBasis basisFor(const Scene& scene, int width, int height) {
    const Camera& c = scene.camera;
    return glsl::cameraBasis(c.position, c.lookAt, c.up, c.fovY, float(width) / float(height));
}

constexpr float kNear = 1e-3f;   // world units in front of the eye where segments are cut

} // namespace

std::optional<ViewHit> viewHit(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                               ImagePoint point) {
    const glsl::CameraBasis b = basisFor(scene, width, height);
    // Image y runs down, ndc y up (camera.glsl: (-1, -1) is the bottom-left corner).
    const glm::vec2 ndc(point.x / float(width) * 2.0f - 1.0f, 1.0f - point.y / float(height) * 2.0f);
    const glsl::Ray ray = glsl::cameraRay(b, ndc);
    if (geometry.instances.empty()) return std::nullopt;
    glsl::cpuTraversal.geometry = &geometry;
    glsl::TraceRecord rec;
    const bool hit = glsl::traceScene(ray, glsl::FLOAT_MAX, false, rec);
    std::optional<ViewHit> out;
    if (hit) {
        const glsl::SurfaceHit s = glsl::surfaceAt(ray, rec);
        out = ViewHit{rec.t, rec.t * glm::dot(ray.dir, b.forward), int(glsl::instanceObjectId(geometry.instances[rec.instance])),
                      int(s.material), s.position};
    }
    glsl::cpuTraversal.geometry = nullptr;
    return out;
}

std::optional<int> pickObject(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                              ImagePoint point) {
    const auto hit = viewHit(scene, geometry, width, height, point);
    if (!hit) return std::nullopt;
    return hit->object;
}

std::optional<int> pickObject(const Scene& scene, int width, int height, ImagePoint point) {
    return pickObject(scene, buildSceneGeometry(scene), width, height, point);
}

Box objectBounds(const Sphere& sphere) {
    const Sphere w = worldSphere(sphere);
    return Box{w.center - glm::vec3(w.radius), w.center + glm::vec3(w.radius)};
}

std::optional<Box> objectBounds(const Scene& scene, const SceneGeometry& geometry, int object) {
    const auto r = objectRef(scene, object);
    if (!r) return std::nullopt;
    if (!r->mesh) return objectBounds(scene.spheres[std::size_t(r->index)]);
    if (std::size_t(r->index) >= geometry.meshBounds.size()) return std::nullopt;   // geometry of another scene
    const Aabb world = transformedBounds(geometry.meshBounds[std::size_t(r->index)],
                                         geometry.meshesInWorld
                                             ? glm::mat4(1.0f)
                                             : transformMatrix(scene.meshes[std::size_t(r->index)].transform));
    if (world.empty()) return std::nullopt;
    return Box{world.min, world.max};
}

namespace {

// Camera-space coordinates: x along right, y along up, z along forward.
glm::vec3 toCamera(const glsl::CameraBasis& b, glm::vec3 p) {
    const glm::vec3 d = p - b.origin;
    return {glm::dot(d, b.right), glm::dot(d, b.up), glm::dot(d, b.forward)};
}

ImagePoint toImage(const glsl::CameraBasis& b, int width, int height, glm::vec3 c) {
    // Inverse of cameraRay: ndc = (x / (z·tan·aspect), y / (z·tan)).
    const float nx = c.x / (c.z * b.tanHalfFovY * b.aspect);
    const float ny = c.y / (c.z * b.tanHalfFovY);
    return {(nx + 1.0f) * 0.5f * float(width), (1.0f - ny) * 0.5f * float(height)};
}

} // namespace

std::optional<ImagePoint> projectPoint(const Scene& scene, int width, int height, glm::vec3 p) {
    const glsl::CameraBasis b = basisFor(scene, width, height);
    const glm::vec3 c = toCamera(b, p);
    if (c.z <= kNear) return std::nullopt;
    return toImage(b, width, height, c);
}

std::vector<Segment> projectBox(const Scene& scene, int width, int height, const Box& box) {
    std::array<glm::vec3, 8> corners;
    for (int i = 0; i < 8; ++i)
        corners[std::size_t(i)] = glm::vec3(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                                            i & 4 ? box.hi.z : box.lo.z);
    return projectCorners(scene, width, height, corners);
}

std::vector<Segment> projectCorners(const Scene& scene, int width, int height, const std::array<glm::vec3, 8>& world) {
    const glsl::CameraBasis b = basisFor(scene, width, height);
    std::array<glm::vec3, 8> corners;
    for (std::size_t i = 0; i < 8; ++i) corners[i] = toCamera(b, world[i]);
    std::vector<Segment> out;
    for (int i = 0; i < 8; ++i) {
        for (int axis = 1; axis < 8; axis <<= 1) {
            if (i & axis) continue;   // each edge once, from its lower corner
            glm::vec3 p = corners[std::size_t(i)];
            glm::vec3 q = corners[std::size_t(i | axis)];
            if (p.z <= kNear && q.z <= kNear) continue;
            // Cut the part behind the near plane (straight lines stay straight in projection).
            if (p.z < kNear) p = p + (q - p) * ((kNear - p.z) / (q.z - p.z));
            if (q.z < kNear) q = q + (p - q) * ((kNear - q.z) / (p.z - q.z));
            out.push_back({toImage(b, width, height, p), toImage(b, width, height, q)});
        }
    }
    return out;
}

std::optional<Segment> projectSegment(const Scene& scene, int width, int height, glm::vec3 a, glm::vec3 b) {
    const glsl::CameraBasis basis = basisFor(scene, width, height);
    glm::vec3 p = toCamera(basis, a), q = toCamera(basis, b);
    if (p.z <= kNear && q.z <= kNear) return std::nullopt;
    if (p.z < kNear) p = p + (q - p) * ((kNear - p.z) / (q.z - p.z));
    if (q.z < kNear) q = q + (p - q) * ((kNear - q.z) / (p.z - q.z));
    return Segment{toImage(basis, width, height, p), toImage(basis, width, height, q)};
}

} // namespace raylab::ui
