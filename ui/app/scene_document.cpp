#include "app/scene_document.h"

#include "app/scene_change.h"
#include "app/scene_object.h"
#include "scene/scene_keys.h"
#include "scene/scene_loader.h"
#include "scene/scene_save.h"

#include <cstdio>
#include <fstream>

namespace raylab::ui {
namespace {

// Logs what an edit cost where it is not obvious (a displacement key: the mesh's triangles and
// time); true.
bool reportEdit(Log& log, const Scene& scene, const std::string& key) {
    const std::vector<std::string> parts = splitKey(key);
    if (parts.size() != 3 || parts[0] != "objects" || parts[2].rfind("displacement_", 0) != 0) return true;
    const auto r = objectRef(scene, std::stoi(parts[1]));
    if (!r || !r->mesh) return true;
    const Mesh& m = scene.meshes[std::size_t(r->index)];
    char text[160];
    if (m.displacement.texture.empty())
        std::snprintf(text, sizeof text, "not displaced (no displacement_texture): %zu triangles", m.triangles.size());
    else
        std::snprintf(text, sizeof text, "displaced again: %zu -> %zu triangles in %.1f ms", m.displacement.trianglesBefore,
                      m.triangles.size(), m.displacement.milliseconds);
    log.info(key + ": " + text);
    return true;
}

} // namespace

bool SceneDocument::open(const std::filesystem::path& file) {
    Scene next;
    try {
        next = loadScene(file);
    } catch (const std::exception& e) {
        lastError_ = e.what();
        log_.error(lastError_ + (loaded_ ? " (the previous scene stays)" : ""));
        // Keep watching the broken file: fixing it on disk reloads it.
        std::error_code ec;
        if (!loaded_ || std::filesystem::equivalent(file, path_, ec)) watcher_.watch(file);
        return false;
    }
    // The same file again with only objects moved: keep the meshes' BVHs.
    std::error_code ec;
    const bool sameFile = loaded_ && std::filesystem::equivalent(file, path_, ec);
    const Trigger trigger = sameFile ? reloadTrigger(scene_, next) : Trigger::ReloadScene;
    if (!apply(std::move(next), trigger)) return false;
    path_ = file;
    watcher_.watch(file);
    log_.info("opened " + file.string() + " (" + std::to_string(objectCount(scene_)) + " objects, " +
              std::to_string(scene_.materials.size()) + " materials" +
              (trigger == Trigger::MoveObjects ? "; only objects moved: the meshes' BVHs stay" : "") + ")");
    return true;
}

bool SceneDocument::reloadIfChanged() {
    if (!watcher_.changed()) return false;
    const std::filesystem::path file = watcher_.file();
    log_.info(file.string() + " changed on disk: reloading");
    return open(file);
}

bool SceneDocument::save(const std::filesystem::path& file) {
    try {
        saveSceneFile(scene_, file);   // paths relative to `file`, atomic, a backup until complete
        log_.info("saved the scene to " + file.string());
        return true;
    } catch (const std::exception& e) {
        lastError_ = e.what();
        log_.error(lastError_);
        return false;
    }
}

bool SceneDocument::set(const std::string& key, const std::string& valueText) {
    Scene next = scene_;
    try {
        const Trigger t = setParam(next, key, valueText);
        return apply(std::move(next), t) && reportEdit(log_, scene_, key);
    } catch (const std::exception& e) {
        lastError_ = std::string("set ") + e.what();
        log_.error(lastError_);
        return false;
    }
}

bool SceneDocument::set(const SceneParam& param, const ParamValue& value) {
    Scene next = scene_;
    try {
        const Trigger t = setParam(next, param, value);
        return apply(std::move(next), t) && reportEdit(log_, scene_, param.key);
    } catch (const std::exception& e) {
        lastError_ = e.what();
        log_.error(lastError_);
        return false;
    }
}

void SceneDocument::changed(Trigger trigger) { apply(scene_, trigger); }

bool SceneDocument::apply(Scene next, Trigger trigger) {
    if (!renderer_.ready()) {
        scene_ = std::move(next);
        loaded_ = true;
        return false;
    }
    if (trigger == Trigger::RecompileShader) {
        scene_ = std::move(next);
        loaded_ = true;
        return renderer_.reloadShaders();
    }
    if (trigger == Trigger::Redisplay && loaded_) {
        scene_ = std::move(next);
        renderer_.redisplay();
        return true;
    }
    if (!renderer_.upload(next, trigger)) return false;
    scene_ = std::move(next);
    loaded_ = true;
    lastError_.clear();
    renderer_.restart();
    return true;
}

} // namespace raylab::ui
