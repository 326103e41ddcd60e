#pragma once
// Which side of its surface a ray can leave an object by and never meet it again. A mesh all of
// whose vertices lie behind (or on) the plane of every one of its faces, the front being the side
// of the winding normal (p1 − p0) × (p2 − p0), is the boundary, or part of it, of a convex body;
// a ray that leaves one of its faces towards the front stays in front of that face's plane and so
// in front of the whole mesh. The same with "in front of" for the back side. A planar mesh has
// both sides, a closed convex one the side its windings face outwards, a sphere its outside. The
// tracer leaves such an object out of the next ray's search (bvh_traversal.glsl): a test that could
// only find a self-intersection, skipped (bench/mesh_rays.md, "A ray does not search the object it
// leaves").
#include "scene/scene.h"

namespace raylab {

// INSTANCE_ESCAPES_FRONT | INSTANCE_ESCAPES_BACK of shaders/include/geometry_types.glsl, or
// neither, for the mesh's triangles over its positions as they are (the floats the GPU gets).
// Decided in double precision with a relative tolerance of 1e-12, far below float's 6e-8: a
// vertex off a face's plane by less than that counts as on it. A mesh larger than
// kEscapeSidesMaxWork (triangles × vertices) is not examined and gets neither side.
unsigned meshEscapeSides(const Mesh& mesh);
constexpr std::size_t kEscapeSidesMaxWork = std::size_t(1) << 22;

} // namespace raylab
