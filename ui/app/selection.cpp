#include "app/selection.h"

#include "app/scene_object.h"

#include <string>
#include <vector>

namespace raylab::ui {

void Selection::select(int object, int material) {
    const bool valid = objectRef(scene_, object).has_value();
    object_ = valid ? object : -1;
    material_ = valid ? material : -1;
    light_ = -1;
}

void Selection::selectLight(int light) {
    select(-1);
    light_ = light >= 0 && light < int(scene_.lights.size()) ? light : -1;
}

int Selection::editedMaterial() const {
    const std::vector<int> materials = objectMaterials(scene_, object_);
    if (materials.empty()) return -1;
    for (const int m : materials)
        if (m == material_) return m;
    return materials.front();
}

std::optional<int> Selection::pick(const SceneGeometry& geometry, int width, int height, ImagePoint p, Log& log) {
    const std::optional<ViewHit> hit = viewHit(scene_, geometry, width, height, p);
    if (!hit) {
        select(-1);
        log.info("picked nothing (sky)");
        return std::nullopt;
    }
    select(hit->object, hit->material);
    const std::string material = hit->material >= 0 && hit->material < int(scene_.materials.size())
                                     ? scene_.materials[std::size_t(hit->material)].name
                                     : "?";
    const ObjectRef r = *objectRef(scene_, hit->object);
    log.info("picked object " + std::to_string(hit->object) + " (material " + material + "), " +
             (r.mesh ? "mesh " : "sphere ") + std::to_string(r.index));
    return hit->object;
}

} // namespace raylab::ui
