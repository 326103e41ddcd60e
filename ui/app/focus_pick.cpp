#include "app/focus_pick.h"

namespace raylab::ui {

std::optional<float> focusDistanceAt(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                                     ImagePoint point) {
    const std::optional<ViewHit> hit = viewHit(scene, geometry, width, height, point);
    if (!hit) return std::nullopt;
    return hit->depth;
}

} // namespace raylab::ui
