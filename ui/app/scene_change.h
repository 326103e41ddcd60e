#pragma once
// What a reloaded scene file changed, so a reload does the least work that keeps the image right:
// when only objects moved (transforms, sphere centres and radii), the tracer keeps the meshes'
// BVHs and rebuilds the top level (Trigger::MoveObjects); anything else reloads the scene.
#include "scene/parameters.h"
#include "scene/scene.h"

namespace raylab::ui {

// MoveObjects when `after` differs from `before` at most in where its objects are (same objects,
// meshes, materials, textures, camera, render settings and sky), else ReloadScene. Files the
// scene names are compared by their loaded contents (meshes, textures), except the sky map, which
// is compared by path.
Trigger reloadTrigger(const Scene& before, const Scene& after);

} // namespace raylab::ui
