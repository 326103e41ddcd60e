#pragma once
// Click-to-focus: the focus distance that makes the surface seen at an image point sharp. The
// thin lens of shaders/include/camera.glsl focuses on the plane at focus_distance along the view
// axis (not on a sphere around the eye), so the distance is the hit's depth along the camera's
// forward axis: t·(dir · forward) for the pixel's pinhole ray. The hit is the one a click picks
// (viewHit in app/view_geometry.h: the tracer's own BVH traversal on the CPU), so spheres and
// meshes both count.
#include "accel/scene_geometry.h"
#include "app/view_geometry.h"

#include <optional>

namespace raylab::ui {

// Depth along the view axis of the surface hit by the pinhole ray through image point (x, y) of a
// width × height image (top-left origin, as view_geometry.h); nullopt for the sky.
std::optional<float> focusDistanceAt(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                                     ImagePoint point);

} // namespace raylab::ui
