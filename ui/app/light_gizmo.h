#pragma once
// The light gizmos of the Overlays panel: image-space lines for each light of Scene::lights,
// projected with the tracer's camera (app/view_geometry.h), so a gizmo sits where the light's
// position shows in the traced image. The viewport draws them; the geometry is tested here.
#include "app/view_geometry.h"
#include "scene/scene.h"

#include <vector>

namespace raylab::ui {

inline constexpr int kGizmoCircleSegments = 16;    // a circle (the spot's cone rim, the sun symbol)
inline constexpr float kGizmoSizeOfHeight = 0.03f; // a star's radius, as a fraction of the image height

// The lines of light `light`'s gizmo in a width × height image (empty when out of range or nothing
// of it is in front of the camera):
//  - point: a star of 4 lines through its projected position;
//  - spot: that star plus its outer cone, cut at a length of a third of the light's distance to
//    the eye: the rim (kGizmoCircleSegments lines) and 4 lines from the apex to it;
//  - distant: a sun symbol (a circle) at the image centre and an arrow from there along the
//    direction the light travels, as seen from the eye (only the circle when it travels along
//    the view axis).
std::vector<Segment> lightGizmo(const Scene& scene, int width, int height, int light);

} // namespace raylab::ui
