#pragma once
// Scene -> the file format, key by key through the parameter tables, so what the loader reads the
// writer writes.
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace raylab {

// Writes a scene back in the file format: every key, all materials, all objects. File paths (the
// table's pathKeys()) are written relative to the directory of `savedFile`, or of the scene's own
// sourcePath when none is given, so the text loads back to the same scene from there: loading
// sceneToJson(s, f).dump() as f gives back s (except sourcePath). Throws SceneError when a sphere
// refers to a material index that does not exist.
nlohmann::json sceneToJson(const Scene& scene, const std::filesystem::path& savedFile = {});

// Rewrites every path key of `doc` (pathKeys()) that is relative to directory `from` so that it is
// relative to directory `to` (both taken from the working directory when relative).
void rebasePaths(nlohmann::json& doc, const std::filesystem::path& from, const std::filesystem::path& to);

} // namespace raylab
