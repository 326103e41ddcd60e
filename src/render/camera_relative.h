#pragma once
// Camera-relative coordinates: the GPU works in float32, whose spacing at 10^5 is 1/128, so the host
// moves the world by −origin in double precision before upload and the GPU sees small numbers near
// the camera. Meshes stay in object space; only placements (sphere centres, instance translations,
// the camera) move.
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace raylab {

// The scene's objects and camera moved by −origin, positions computed in double and rounded once.
// Spheres come back with their transform folded into centre and radius. Textures are left out (the
// geometry and the light list never read them); everything else is copied as it is.
Scene cameraRelative(const Scene& scene, const glm::dvec3& origin);

// The scene less its textures (the geometry and the light list never read them): what the copies
// made for the GPU start from (cameraRelative, render/baked_mesh_transforms.h).
Scene withoutTextures(const Scene& scene);

// scene/transform.cpp's T · Rz · Ry · Rx · S applied to a point, in double.
glm::dvec3 transformPointInDouble(const Transform& t, const glm::dvec3& p);

// World → camera-relative for one point, in double, rounded once.
glm::vec3 relativePoint(const glm::vec3& world, const glm::dvec3& origin);

// Whether the camera has moved so far from the origin in use that its own coordinates would lose
// precision against the scene near it: farther than kRebaseViews viewing distances (eye to look_at).
// Inside that region a camera move keeps the uploaded scene, so a drag re-uploads nothing.
inline constexpr double kRebaseViews = 16.0;
bool needsRebase(const Camera& camera, const glm::dvec3& origin);

} // namespace raylab
