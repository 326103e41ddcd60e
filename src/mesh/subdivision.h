#pragma once
// Midpoint subdivision: every triangle split into four at its edge midpoints, the surface unchanged
// (flat triangles stay flat) until something moves the new vertices (mesh/displacement.h).
#include "scene/scene.h"

namespace raylab {

// `levels` rounds of 1-to-4 splits: 4^levels triangles per triangle. An edge's midpoint is one
// vertex for both triangles that share the edge, so a closed mesh stays closed. Normals (renormalised)
// and uvs are interpolated linearly; per-triangle materials go to all four children.
Mesh subdivideMesh(const Mesh& mesh, int levels);

} // namespace raylab
