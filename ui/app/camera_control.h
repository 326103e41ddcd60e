#pragma once
// Camera moves of the viewer on the scene's look-at camera. Orbit turns the eye around the look-at
// point; turn (fly, arrow keys) turns the view direction around the eye; move (WASD/QE) shifts
// eye and look-at together along the view basis. Angles in radians. Pure maths, testable.
#include "scene/scene.h"

namespace raylab::ui {

// yaw about the world up axis (camera.up), pitch about the camera's right axis; pitch stops short
// of the poles so up never becomes parallel to the view axis.
void orbitCamera(Camera& camera, float yaw, float pitch);
void turnCamera(Camera& camera, float yaw, float pitch);
// forward/right/up in world units along the camera's forward, right and world-up directions.
void moveCamera(Camera& camera, float forward, float right, float up);
// Moves the eye toward the look-at point by a factor (0.9 = 10 % closer), never onto it.
void dollyCamera(Camera& camera, float factor);

} // namespace raylab::ui
