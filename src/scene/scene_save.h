#pragma once
// Saving a scene to disk so that nothing is lost: paths rewritten for the new file's directory, and
// no moment at which the file is half written or missing.
#include "scene/scene.h"

#include <filesystem>

namespace raylab {

// Writes sceneToJson(scene, file) to `file`. The text goes to a temporary file beside it, which
// is flushed to disk and then renamed over `file`; a file already there is kept as `file` + ".bak"
// until the new one is in place, then removed. On failure `file` is as it was and the temporary
// file is gone. Throws SceneError "FILE: error: cannot write: why".
void saveSceneFile(const Scene& scene, const std::filesystem::path& file);

// Where saveSceneFile keeps the previous file while it writes: "scene.json.bak" beside "scene.json".
std::filesystem::path backupPath(const std::filesystem::path& file);

} // namespace raylab
