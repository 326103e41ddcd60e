#pragma once
// The scene document: the scene the viewer shows, the file it came from (watched for changes), its
// typed edits, saving, and the last error of a load, compile or edit. A changed scene reaches the
// tracer through SceneRenderer (the Viewer's render session). No GL here.
#include "app/file_watcher.h"
#include "app/log.h"
#include "scene/scene_keys.h"
#include "scene/parameters.h"
#include "scene/scene.h"

#include <filesystem>
#include <string>

namespace raylab::ui {

// What the document asks of the renderer that traces its scene.
class SceneRenderer {
public:
    virtual ~SceneRenderer() = default;
    virtual bool ready() const = 0;   // a tracer exists (its shaders compiled)
    virtual bool reloadShaders() = 0;
    virtual void redisplay() = 0;
    // Gives `next` to the tracer as `trigger` says, while the document still holds the previous
    // scene; on failure records the error, puts the previous scene back and returns false.
    virtual bool upload(const Scene& next, Trigger trigger) = 0;
    virtual void restart() = 0;   // after an upload, once the document holds the new scene
};

class SceneDocument {
public:
    SceneDocument(Log& log, SceneRenderer& renderer) : log_(log), renderer_(renderer) {}

    // Loads a scene file; on failure logs the error (file:line), keeps the previous scene running
    // and returns false.
    bool open(const std::filesystem::path& file);
    // Reloads when the file changed on disk; call once a frame. True when it reloaded.
    bool reloadIfChanged();
    bool save(const std::filesystem::path& file);

    // Changes one key ("camera.fov", "materials.red.albedo", "objects.2.radius"); logs and returns
    // false when the key or value is bad.
    bool set(const std::string& key, const std::string& valueText);
    bool set(const SceneParam& param, const ParamValue& value);
    // After changing scene() directly (camera moves): does what `trigger` implies.
    void changed(Trigger trigger);
    // Makes `next` the scene, doing the least work `trigger` allows (app/scene_change.h).
    bool apply(Scene next, Trigger trigger);

    Scene& scene() { return scene_; }
    const Scene& scene() const { return scene_; }
    bool loaded() const { return loaded_; }   // a scene was applied at least once
    const std::filesystem::path& path() const { return path_; }
    // The most recent error of a load, reload, compile or edit ("" once something succeeds).
    const std::string& lastError() const { return lastError_; }
    void setError(std::string error) { lastError_ = std::move(error); }
    void clearError() { lastError_.clear(); }

private:
    Log& log_;
    SceneRenderer& renderer_;
    Scene scene_;
    bool loaded_ = false;
    std::filesystem::path path_;
    FileWatcher watcher_;
    std::string lastError_;
};

} // namespace raylab::ui
