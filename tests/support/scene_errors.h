#pragma once
// The message of the SceneError a scene text raises, for tests of located error messages.
#include "scene/scene_loader.h"

#include <string>
#include <vector>

namespace raylab::test {

// What parseScene(text, file, overrides) throws, or `none` when the text is a valid scene.
inline std::string sceneErrorOf(const std::string& text, const std::vector<std::string>& overrides = {},
                                const std::string& file = "test.json", const std::string& none = "<no error>") {
    try {
        parseScene(text, file, overrides);
    } catch (const SceneError& e) {
        return e.what();
    }
    return none;
}

} // namespace raylab::test
