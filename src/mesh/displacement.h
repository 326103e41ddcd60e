#pragma once
// Displacement mapping on loading: a mesh is subdivided, then its vertices move along their normals
// by a height, and the normals are recomputed from the moved surface, so the BVH and every ray see
// the displaced shape, not a shading trick.
#include "scene/scene.h"
#include "texture/texture.h"

#include <cstddef>
#include <functional>

namespace raylab {

// Most triangles a displaced mesh may have after subdivision (each costs 64 bytes on the GPU plus
// its BVH share and vertices).
inline constexpr std::size_t kMaxDisplacedTriangles = 4'000'000;

// Moves vertex i along its unit normal by height(i) and recomputes the normals (mesh/vertex_normals.h),
// each kept on the side its normal faced. A mesh without normals is first given them from its shape.
void displaceAlongNormals(Mesh& mesh, const std::function<float(std::size_t vertex)>& height);

// The height a displacement texture gives at uv: level 0's red channel, bilinear, repeating
// (shaders/include/texture.glsl's filter).
float displacementHeight(const Texture& texture, glm::vec2 uv);

// subdivideMesh by mesh.displacement.subdivision, then displaceAlongNormals by displacement.scale ×
// displacementHeight at each vertex's uv; records the triangles before and the time taken in
// mesh.displacement. The mesh needs uvs.
void displaceMesh(Mesh& mesh, const Texture& texture);

} // namespace raylab
