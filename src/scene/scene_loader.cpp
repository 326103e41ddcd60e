#include "scene/scene_loader.h"

#include "scene/json_locator.h"
#include "scene/json_parse.h"
#include "scene/scene_builder.h"
#include "scene/scene_overrides.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace raylab {

using namespace scenefmt;

Scene parseScene(std::string_view text, const std::string& fileName, const std::vector<std::string>& overrides) {
    ParseResult parsed = parseJson(text);
    const JsonLocator locator(text);
    if (std::string error = documentError(parsed, locator, fileName); !error.empty()) throw SceneError(error);
    Json& doc = parsed.doc;

    std::vector<AppliedOverride> applied;
    for (const std::string& o : overrides) applied.push_back(applyOverride(doc, o));

    Scene scene;
    scene.sourcePath = fileName;
    try {
        buildScene(doc, scene);
    } catch (const ValidationFailure& f) {
        throw SceneError(placeFailure(f, fileName, locator, applied));
    }
    return scene;
}

Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    const std::string name = file.string();
    errno = 0;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
    if (!f) throw SceneError(name + ": error: cannot read: " + std::strerror(errno));
    std::string text;
    char buffer[65536];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f.get())) > 0) text.append(buffer, n);
    if (std::ferror(f.get())) {
        const int err = errno != 0 ? errno : EIO;
        throw SceneError(name + ": error: cannot read: " + std::strerror(err));
    }
    Scene scene = parseScene(text, name, overrides);
    scene.sourcePath = file;
    return scene;
}

} // namespace raylab
