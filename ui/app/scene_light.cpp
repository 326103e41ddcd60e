#include "app/scene_light.h"

#include "inspect/light_names.h"
#include "scene/parameters.h"

#include <algorithm>

namespace raylab::ui {

std::string lightLabel(const Scene& scene, int light) {
    if (light < 0 || light >= int(scene.lights.size())) return "?";
    return lightName(scene.lights[std::size_t(light)].type, light);
}

std::vector<std::string> lightKeys(const Scene& scene, int light) {
    if (light < 0 || light >= int(scene.lights.size())) return {};
    const std::vector<std::string_view> own = lightKeysOf(scene.lights[std::size_t(light)].type);
    std::vector<std::string> keys;
    for (const LightParamSpec& p : lightParameters())
        if (std::find(own.begin(), own.end(), p.name()) != own.end())
            keys.push_back("lights." + std::to_string(light) + "." + std::string(p.name()));
    return keys;
}

} // namespace raylab::ui
