#include "app/view_geometry.h"

#include "shaders/include/camera.glsl"
#include "shaders/include/sphere.glsl"

namespace raylab::ui {
namespace {

glsl::CameraBasis basisFor(const Scene& scene, int width, int height) {
    const Camera& c = scene.camera;
    return glsl::cameraBasis(c.position, c.lookAt, c.up, c.fovY, float(width) / float(height));
}

glsl::Ray rayThrough(const Scene& scene, int width, int height, ImagePoint p) {
    // Image y runs down, ndc y up (camera.glsl: (-1, -1) is the bottom-left corner).
    const glm::vec2 ndc(p.x / float(width) * 2.0f - 1.0f, 1.0f - p.y / float(height) * 2.0f);
    return glsl::cameraRay(basisFor(scene, width, height), ndc);
}

struct Nearest {
    int index = -1;
    float t = 0.0f;
};

Nearest nearestHit(const Scene& scene, const glsl::Ray& ray) {
    // The loop of shaders/include/scene_intersect.glsl.
    Nearest n;
    float tMax = glsl::FLOAT_MAX;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        const float t = glsl::intersectSphere(ray, s.center, s.radius, 0.0f, tMax);
        if (t > 0.0f) {
            tMax = t;
            n.index = int(i);
            n.t = t;
        }
    }
    return n;
}

constexpr float kNear = 1e-3f;   // world units in front of the eye where segments are cut

} // namespace

std::optional<int> pickObject(const Scene& scene, int width, int height, ImagePoint point) {
    const Nearest n = nearestHit(scene, rayThrough(scene, width, height, point));
    if (n.index < 0) return std::nullopt;
    return n.index;
}

std::optional<float> pickDistance(const Scene& scene, int width, int height, ImagePoint point) {
    const Nearest n = nearestHit(scene, rayThrough(scene, width, height, point));
    if (n.index < 0) return std::nullopt;
    return n.t;
}

Box objectBounds(const Sphere& sphere) {
    return Box{sphere.center - glm::vec3(sphere.radius), sphere.center + glm::vec3(sphere.radius)};
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
