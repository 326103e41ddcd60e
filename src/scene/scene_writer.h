#pragma once
// Scene -> the file format, key by key through the parameter tables, so what the loader reads the
// writer writes.
#include "scene/scene.h"

#include <nlohmann/json.hpp>

namespace raylab {

// Writes a scene back in the file format: every key, all materials, all objects. Round-trips:
// parseScene(sceneToJson(s).dump(), ...) gives back s (except sourcePath). Throws SceneError when a
// sphere refers to a material index that does not exist.
nlohmann::json sceneToJson(const Scene& scene);

} // namespace raylab
