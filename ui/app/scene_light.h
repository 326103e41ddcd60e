#pragma once
// The viewer's lights: light i is Scene::lights[i], edited as `lights.i.KEY` (scene/scene_keys.h)
// through the scene document like any other key, so an edit restarts the image and re-uploads the
// tracer's lights. The outliner lists them after the objects; the Light panel edits the selected one.
#include "scene/scene.h"

#include <string>
#include <vector>

namespace raylab::ui {

// The outliner's text: "point light 0", "spot 1", "sun 2" (inspect/light_names.h).
std::string lightLabel(const Scene& scene, int light);
// The keys the Light panel shows for the light, its type's keys in the parameter table's order
// ("lights.1.position", ...); empty when out of range.
std::vector<std::string> lightKeys(const Scene& scene, int light);

} // namespace raylab::ui
