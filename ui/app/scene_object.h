#pragma once
// The viewer's objects, one numbering for every part of it: spheres first (object i is
// scene.spheres[i]), then mesh instances (object spheres.size() + j is scene.meshes[j]). It is the
// order sceneToJson writes "objects" in, what `objects.N.KEY` edits, the outliner's rows, what a
// click picks (the GPU instances' object id, instanceObjectId in geometry_types.glsl), the boxes
// of the overlay and the colours of the object-id debug view.
#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab::ui {

struct ObjectRef {
    bool mesh = false;
    int index = -1;   // into scene.spheres or scene.meshes
};

int objectCount(const Scene& scene);
// Where object `object` lives; nullopt when out of range.
std::optional<ObjectRef> objectRef(const Scene& scene, int object);
// The object's own `material` (-1 when out of range).
int objectMaterial(const Scene& scene, int object);
// Every material the object shows: a sphere's one; a mesh's own `material` (when some triangle
// uses it) and its glTF per-triangle materials, in the order the triangles first use them.
std::vector<int> objectMaterials(const Scene& scene, int object);
// The outliner's text: "0  sphere  ground", "5  mesh  white", "6  mesh  box.gltf  (3 materials)".
std::string objectLabel(const Scene& scene, int object);

} // namespace raylab::ui
