#include "app/scene_change.h"

#include "scene/scene_loader.h"

namespace raylab::ui {
namespace {

bool sameMeshData(const Mesh& a, const Mesh& b) {
    return a.positions == b.positions && a.normals == b.normals && a.uvs == b.uvs && a.triangles == b.triangles &&
           a.triangleMaterials == b.triangleMaterials;
}

bool sameTextures(const Scene& a, const Scene& b) {
    if (a.textures.size() != b.textures.size()) return false;
    for (std::size_t i = 0; i < a.textures.size(); ++i) {
        const Texture& x = a.textures[i];
        const Texture& y = b.textures[i];
        if (x.levels.size() != y.levels.size() || (!x.levels.empty() && x.levels[0].texels != y.levels[0].texels))
            return false;
    }
    return true;
}

} // namespace

Trigger reloadTrigger(const Scene& before, const Scene& after) {
    if (before.spheres.size() != after.spheres.size() || before.meshes.size() != after.meshes.size())
        return Trigger::ReloadScene;
    for (std::size_t i = 0; i < before.meshes.size(); ++i)
        if (!sameMeshData(before.meshes[i], after.meshes[i])) return Trigger::ReloadScene;
    if (!sameTextures(before, after)) return Trigger::ReloadScene;
    // Everything else as the file states it, with the placements put back: equal means only they changed.
    Scene probe = after;
    for (std::size_t i = 0; i < probe.spheres.size(); ++i) {
        probe.spheres[i].center = before.spheres[i].center;
        probe.spheres[i].radius = before.spheres[i].radius;
        probe.spheres[i].transform = before.spheres[i].transform;
    }
    for (std::size_t i = 0; i < probe.meshes.size(); ++i) probe.meshes[i].transform = before.meshes[i].transform;
    return sceneToJson(probe) == sceneToJson(before) ? Trigger::MoveObjects : Trigger::ReloadScene;
}

} // namespace raylab::ui
