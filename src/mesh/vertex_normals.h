#pragma once
// Smooth vertex normals from a triangle mesh's shape.
#include <glm/glm.hpp>

#include <vector>

namespace raylab {

// Per vertex, the area-weighted mean of the normals e01 × e02 of the triangles around it
// (unnormalised cross products summed, then normalised); (0, 0, 0) for a vertex that no triangle of
// non-zero area uses.
std::vector<glm::vec3> vertexNormals(const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles);

} // namespace raylab
