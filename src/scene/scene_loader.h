#pragma once
// Scene files: JSON (with // and /* */ comments) -> validated Scene, and back. The format is
// documented key by key in scenes/FORMAT.md; the keys of "camera", "render" and "sky" come from the
// parameter table in scene/parameters.h.
#include "scene/scene.h"
#include "scene/scene_error.h"
#include "scene/scene_writer.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

// Reads, parses and validates `file`. `overrides` are "dotted.key=value" strings (the renderer's
// --set), e.g. "render.spp=256", "materials.red.albedo=[1,0,0]", "objects.0.radius=2": each value is
// parsed as JSON when it parses, otherwise taken as a string, and written into the parsed document
// (creating missing objects along the path) before validation. Throws SceneError.
Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// Same for text already in memory; `fileName` is used in messages and as Scene::sourcePath.
Scene parseScene(std::string_view text, const std::string& fileName,
                 const std::vector<std::string>& overrides = {});

} // namespace raylab
