#pragma once
// The uniform block the few-objects loops read (shaders/include/few_objects.glsl): each object's
// world box and each sphere, in the top level's order.
#include "accel/scene_geometry.h"

#include "shaders/include/few_objects.glsl"

namespace raylab {

// From the top level as uploaded (camera-relative): instance i's world box, w 1 for a mesh and 0
// for a sphere, and sphere k as the sphere buffer holds it. Entries past the scene's objects are
// 0; a scene of more than FEW_OBJECTS_MAX objects walks the top-level BVH, which reads no block,
// and its block holds the first FEW_OBJECTS_MAX.
glsl::FewObjectsBlock fewObjectsBlock(const SceneGeometry& top);

} // namespace raylab
