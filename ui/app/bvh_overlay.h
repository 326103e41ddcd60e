#pragma once
// The BVH-level overlay: the boxes of one level of the top-level BVH (over the objects) or of the
// meshes' BVHs (in each mesh's object space, drawn through its transform), projected with the
// tracer's camera (app/view_geometry.h). The boxes are the ones the tracer traverses: read from the
// built SceneGeometry (accel/scene_geometry.h), not rebuilt.
#include "accel/scene_geometry.h"
#include "app/view_geometry.h"

#include <cstdint>
#include <vector>

namespace raylab::ui {

// The boxes of the nodes `depth` edges below `root` of a flattened BVH, and of the leaves above
// that depth, so that a level covers every primitive (depth 0: the root's box). Empty nodes are
// left out.
std::vector<Box> bvhLevel(const std::vector<glsl::GpuBvhNode>& nodes, std::uint32_t root, int depth);

// Image segments of the top-level BVH's level `depth`.
std::vector<Segment> topLevelBvhSegments(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                                         int depth);
// Image segments of level `depth` of every mesh's BVH, each box through its object's transform.
std::vector<Segment> meshBvhSegments(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                                     int depth);

} // namespace raylab::ui
