#pragma once
// Names for the lights a light sample picks, in the tracer's numbering (render/light_list.h):
// emissive spheres, then emissive triangles, then the scene's `lights` in file order; -1 the sky.
// The inspector, its exports and the viewer's outliner name a light the same way.
#include "scene/scene.h"

#include <string>
#include <vector>

namespace raylab {

// "point light 0", "spot 1", "sun 2": a light of Scene::lights by its type and index there.
std::string lightName(Light::Type type, int index);
// Whether no ray can hit the light, so only next-event estimation finds it (pbrt-v4 §12.1): a
// point or spot light, or a distant light without a disc.
bool isDeltaLight(const Light& light);

struct LightNumbering {
    int spheres = 0;            // emissive spheres: lights 0 … S−1
    int triangles = 0;          // emissive triangles: S … S+T−1
    std::vector<Light> lights;  // Scene::lights: S+T …
};
// "sky" (-1), "sphere light 3", "triangle light 12", or lightName() of a scene light; "light N"
// for an index the numbering does not hold.
std::string lightSampleName(const LightNumbering& numbering, int index);
// The scene light behind the index; nullptr for a sphere, a triangle or the sky.
const Light* sceneLight(const LightNumbering& numbering, int index);

} // namespace raylab
