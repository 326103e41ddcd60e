#include "app/light_gizmo.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace raylab::ui {
namespace {

void add(std::vector<Segment>& out, const std::optional<Segment>& s) {
    if (s) out.push_back(*s);
}

void star(std::vector<Segment>& out, ImagePoint c, float r) {
    const float d = r * 0.7071f;
    out.push_back({{c.x - r, c.y}, {c.x + r, c.y}});
    out.push_back({{c.x, c.y - r}, {c.x, c.y + r}});
    out.push_back({{c.x - d, c.y - d}, {c.x + d, c.y + d}});
    out.push_back({{c.x - d, c.y + d}, {c.x + d, c.y - d}});
}

void circle(std::vector<Segment>& out, ImagePoint c, float r) {
    for (int i = 0; i < kGizmoCircleSegments; ++i) {
        const float a0 = glm::two_pi<float>() * float(i) / float(kGizmoCircleSegments);
        const float a1 = glm::two_pi<float>() * float(i + 1) / float(kGizmoCircleSegments);
        out.push_back({{c.x + r * std::cos(a0), c.y + r * std::sin(a0)}, {c.x + r * std::cos(a1), c.y + r * std::sin(a1)}});
    }
}

// Two unit vectors perpendicular to unit `axis` and to each other.
void perpendiculars(glm::vec3 axis, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    u = glm::normalize(glm::cross(axis, helper));
    v = glm::cross(axis, u);
}

void spotCone(std::vector<Segment>& out, const Scene& scene, int w, int h, const Light& l) {
    const glm::vec3 axis = glm::normalize(l.direction);
    const float length = glm::length(l.position - scene.camera.position) / 3.0f;
    const float radius = length * std::tan(glm::radians(std::min(l.outerAngle, 89.0f)));
    glm::vec3 u, v;
    perpendiculars(axis, u, v);
    const glm::vec3 centre = l.position + axis * length;
    auto rim = [&](int i) {
        const float a = glm::two_pi<float>() * float(i) / float(kGizmoCircleSegments);
        return centre + radius * (std::cos(a) * u + std::sin(a) * v);
    };
    for (int i = 0; i < kGizmoCircleSegments; ++i) add(out, projectSegment(scene, w, h, rim(i), rim(i + 1)));
    for (int i = 0; i < kGizmoCircleSegments; i += kGizmoCircleSegments / 4)
        add(out, projectSegment(scene, w, h, l.position, rim(i)));
}

void sunArrow(std::vector<Segment>& out, const Scene& scene, int w, int h, const Light& l, float r) {
    const Camera& cam = scene.camera;
    const glm::vec3 forward = glm::normalize(cam.lookAt - cam.position);
    const float distance = glm::length(cam.lookAt - cam.position);
    const glm::vec3 from = cam.position + forward * distance;
    const std::optional<ImagePoint> c = projectPoint(scene, w, h, from);
    if (!c) return;
    circle(out, *c, r);
    const std::optional<Segment> s =
        projectSegment(scene, w, h, from, from + glm::normalize(l.direction) * (distance * 0.3f));
    if (!s) return;
    const glm::vec2 d(s->b.x - s->a.x, s->b.y - s->a.y);
    if (glm::length(d) < r) return;   // along the view axis: the circle says it all
    const glm::vec2 back = -glm::normalize(d) * r;
    const glm::vec2 side(-back.y, back.x);
    const glm::vec2 tip(s->b.x, s->b.y);
    const glm::vec2 left = tip + back + side * 0.5f, right = tip + back - side * 0.5f;
    out.push_back({{c->x + d.x * r / glm::length(d), c->y + d.y * r / glm::length(d)}, s->b});
    out.push_back({s->b, {left.x, left.y}});
    out.push_back({s->b, {right.x, right.y}});
}

} // namespace

std::vector<Segment> lightGizmo(const Scene& scene, int width, int height, int light) {
    std::vector<Segment> out;
    if (light < 0 || light >= int(scene.lights.size())) return out;
    const Light& l = scene.lights[std::size_t(light)];
    const float r = std::max(3.0f, kGizmoSizeOfHeight * float(height));
    if (l.type == Light::Type::Distant) {
        sunArrow(out, scene, width, height, l, r);
        return out;
    }
    if (const std::optional<ImagePoint> c = projectPoint(scene, width, height, l.position)) star(out, *c, r);
    if (l.type == Light::Type::Spot) spotCone(out, scene, width, height, l);
    return out;
}

} // namespace raylab::ui
