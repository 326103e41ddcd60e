#pragma once
// Object transforms as matrices: world = T · Rz · Ry · Rx · S · local.
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace raylab {

glm::mat4 transformMatrix(const Transform& t);
// The inverse, built from the parts (no general 4×4 inversion, so no extra rounding).
glm::mat4 inverseTransformMatrix(const Transform& t);
// World-space sphere after its transform (centre moved, radius scaled by the uniform scale).
Sphere worldSphere(const Sphere& s);

} // namespace raylab
