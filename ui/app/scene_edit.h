#pragma once
// Edits of a loaded scene by key, as the panels and the automation script make them. Keys are the
// scene file's: "camera.fov", "render.rpp", "materials.red.albedo" (name or index),
// "objects.2.radius". Values are checked against the parameter table (scene/parameters.h), and
// every edit reports its Trigger so the viewer does the least work that keeps the image right.
#include "scene/parameters.h"
#include "scene/scene.h"

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace raylab::ui {

class EditError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// One editable value of a scene: its spec and how to reach it.
struct SceneParam {
    std::string key;
    const ValueSpec* spec = nullptr;
    std::function<ParamValue(const Scene&)> get;
    std::function<void(Scene&, const ParamValue&)> set;
};

// Throws EditError ("unknown key ...; did you mean ...") when the key names nothing in `scene`.
SceneParam resolveParam(const Scene& scene, std::string_view key);

// The value of `text` (JSON: 3, 0.5, [1,0,0], "aces" or aces) for `spec`, range-checked.
ParamValue parseParamValue(const ValueSpec& spec, std::string_view text);

// Sets key = value after checking it; returns what the change implies. Throws EditError naming the
// key; the scene is unchanged then.
Trigger setParam(Scene& scene, std::string_view key, std::string_view valueText);
Trigger setParam(Scene& scene, const SceneParam& param, const ParamValue& value);

// The more expensive of two triggers.
inline Trigger strongerTrigger(Trigger a, Trigger b) { return int(a) > int(b) ? a : b; }

} // namespace raylab::ui
