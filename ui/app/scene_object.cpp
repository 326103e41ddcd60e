#include "app/scene_object.h"

#include <algorithm>
#include <filesystem>

namespace raylab::ui {

int objectCount(const Scene& scene) { return int(scene.spheres.size() + scene.meshes.size()); }

std::optional<ObjectRef> objectRef(const Scene& scene, int object) {
    const int spheres = int(scene.spheres.size());
    if (object < 0 || object >= objectCount(scene)) return std::nullopt;
    return object < spheres ? ObjectRef{false, object} : ObjectRef{true, object - spheres};
}

int objectMaterial(const Scene& scene, int object) {
    const auto r = objectRef(scene, object);
    if (!r) return -1;
    return r->mesh ? scene.meshes[std::size_t(r->index)].material : scene.spheres[std::size_t(r->index)].material;
}

std::vector<int> objectMaterials(const Scene& scene, int object) {
    const auto r = objectRef(scene, object);
    if (!r) return {};
    if (!r->mesh) return {scene.spheres[std::size_t(r->index)].material};
    const Mesh& m = scene.meshes[std::size_t(r->index)];
    if (m.triangleMaterials.empty()) return {m.material};
    std::vector<int> out;
    for (const int t : m.triangleMaterials) {
        const int material = t < 0 ? m.material : t;   // -1: the mesh's own
        if (std::find(out.begin(), out.end(), material) == out.end()) out.push_back(material);
    }
    if (out.empty()) out.push_back(m.material);
    return out;
}

std::string objectLabel(const Scene& scene, int object) {
    const auto r = objectRef(scene, object);
    if (!r) return "?";
    auto materialName = [&](int m) {
        return m >= 0 && m < int(scene.materials.size()) ? scene.materials[std::size_t(m)].name : std::string("?");
    };
    std::string label = std::to_string(object) + (r->mesh ? "  mesh  " : "  sphere  ");
    if (!r->mesh) return label + materialName(scene.spheres[std::size_t(r->index)].material);
    const Mesh& m = scene.meshes[std::size_t(r->index)];
    if (!m.file.empty()) label += std::filesystem::path(m.file).filename().string() + "  ";
    const std::vector<int> materials = objectMaterials(scene, object);
    if (materials.size() == 1) return label + materialName(materials[0]);
    return label + "(" + std::to_string(materials.size()) + " materials)";
}

} // namespace raylab::ui
