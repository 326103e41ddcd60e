#include "accel/escape_sides.h"

#include "shaders/include/geometry_types.glsl"

#include <vector>

namespace raylab {

unsigned meshEscapeSides(const Mesh& mesh) {
    if (mesh.triangles.empty()) return 0u;
    std::vector<bool> used(mesh.positions.size(), false);
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) used.at(t[k]) = true;
    std::vector<glm::dvec3> vertices;
    for (std::size_t v = 0; v < used.size(); ++v)
        if (used[v]) vertices.push_back(glm::dvec3(mesh.positions[v]));
    if (mesh.triangles.size() * vertices.size() > kEscapeSidesMaxWork) return 0u;
    bool front = true;
    bool back = true;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 p0(mesh.positions[t.x]);
        const glm::dvec3 n = glm::cross(glm::dvec3(mesh.positions[t.y]) - p0, glm::dvec3(mesh.positions[t.z]) - p0);
        const double nLength = glm::length(n);
        if (!(nLength > 0.0)) continue;   // degenerate: never hit (triangle.glsl), no plane to leave by
        for (const glm::dvec3& v : vertices) {
            const glm::dvec3 d = v - p0;
            const double side = glm::dot(n, d);
            const double tolerance = 1e-12 * nLength * glm::length(d);
            if (side > tolerance) front = false;
            if (side < -tolerance) back = false;
        }
        if (!front && !back) return 0u;
    }
    return (front ? glsl::INSTANCE_ESCAPES_FRONT : 0u) | (back ? glsl::INSTANCE_ESCAPES_BACK : 0u);
}

} // namespace raylab
