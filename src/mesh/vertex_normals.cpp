#include "mesh/vertex_normals.h"

namespace raylab {

std::vector<glm::vec3> vertexNormals(const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles) {
    std::vector<glm::vec3> sum(positions.size(), glm::vec3(0.0f));
    for (const glm::uvec3& t : triangles) {
        const glm::vec3 n = glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]);
        sum[t.x] += n;
        sum[t.y] += n;
        sum[t.z] += n;
    }
    for (glm::vec3& n : sum)
        if (glm::dot(n, n) > 0.0f) n = glm::normalize(n);
    return sum;
}

} // namespace raylab
