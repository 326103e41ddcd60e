#pragma once
// The scene file's keys as addresses into a loaded Scene: "camera.fov", "sky.map",
// "materials.red.albedo" (a material by name or index), "materials.red.albedo_texture",
// "objects.2.radius", "objects.2.transform.scale", "objects.2.material", "objects.3.displacement_scale"
// (the mesh displaced again), "lights.0.intensity" (a light's own type's keys). Objects are numbered as sceneToJson writes them: spheres first, then meshes. Every key is resolved through the parameter
// table (scene/parameters.h) and checked as the loader checks it, so the viewer's panels, its
// script's `set` and the renderer's --set accept the same keys.
#include "scene/parameters.h"
#include "scene/scene.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

// "KEY: what", e.g. "camera.fov: must be in (0, 180), got 180".
class EditError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// "materials.red.albedo" -> {"materials", "red", "albedo"}. Throws EditError when a part is empty.
std::vector<std::string> splitKey(std::string_view key);

// One value of a scene that a key names. Table keys have a spec and typed get/set; file and name
// keys (a texture, sky.map, an object's material) have setText, which reads a JSON value or bare
// word with the loader's checks.
struct SceneParam {
    std::string key;
    const ValueSpec* spec = nullptr;
    std::function<ParamValue(const Scene&)> get;
    std::function<void(Scene&, const ParamValue&)> set;     // throws EditError for a value the scene refuses
    std::function<void(Scene&, std::string_view)> setText;  // file and name keys only
    Trigger trigger = Trigger::ReloadScene;                 // what a change implies
};

// Throws EditError ("unknown key ...; did you mean ...") when the key names nothing in `scene`.
SceneParam resolveParam(const Scene& scene, std::string_view key);

// Every key resolveParam accepts for `scene`, in file order: sections, then materials, then objects.
std::vector<std::string> sceneKeys(const Scene& scene);

// The value of `text` (JSON: 3, 0.5, [1,0,0], "aces" or aces) for `spec`, range-checked.
ParamValue parseParamValue(const ValueSpec& spec, std::string_view text);

// Sets key = value after checking it; returns what the change implies. Throws EditError naming the
// key; the scene is unchanged then.
Trigger setParam(Scene& scene, std::string_view key, std::string_view valueText);
Trigger setParam(Scene& scene, const SceneParam& param, const ParamValue& value);

} // namespace raylab
