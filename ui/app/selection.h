#pragma once
// The selected object (app/scene_object.h: spheres, then mesh instances; -1 = none), shared by the
// outliner, picking, the box overlay, the Material panel, `selected.KEY` and the BRDF explorer;
// and the material of it that they edit: a click takes the material under the cursor (a glTF
// mesh's per-triangle one), -1 = the object's own. Or, instead of an object, a light of
// Scene::lights (the outliner's rows after the objects, the Light panel, the light gizmos).
#include "app/log.h"
#include "app/view_geometry.h"
#include "scene/scene.h"

#include <optional>

namespace raylab::ui {

class Selection {
public:
    explicit Selection(const Scene& scene) : scene_(scene) {}
    void select(int object, int material = -1);   // out of range: none; deselects the light
    void selectLight(int light);                   // out of range: none; deselects the object
    int object() const { return object_; }
    int light() const { return light_; }           // index into Scene::lights, -1 = none
    int material() const { return material_; }
    // The material the Material panel and `selected.KEY` edit (-1 when nothing is selected).
    int editedMaterial() const;
    // Selects the object seen at image point p of a width × height image (sphere or mesh instance,
    // through the tracer's BVH on the CPU) and the material there; logs what was picked.
    std::optional<int> pick(const SceneGeometry& geometry, int width, int height, ImagePoint p, Log& log);

private:
    const Scene& scene_;
    int object_ = -1;
    int material_ = -1;
    int light_ = -1;
};

} // namespace raylab::ui
