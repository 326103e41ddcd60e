#pragma once
// glTF 2.0 files (.gltf with external or embedded buffers, .glb) → one Mesh, through tinygltf:
// every triangle primitive of the default scene (or the first scene), with the node hierarchy's
// transforms applied to positions and normals; POSITION, NORMAL and TEXCOORD_0 attributes;
// 8-, 16- and 32-bit indices; and the materials (pbrMetallicRoughness, normal and emissive
// textures, KHR_materials_emissive_strength, doubleSided) mapped onto raylab's material with their images
// (external files, data URIs, GLB buffer views) — the mapping is tabled in scenes/FORMAT.md.
// Not read: animations, skins, morph targets, sparse accessors, alpha (ignored with a warning),
// texture coordinate sets other than 0. The occlusion map is kept for the baked-ao debug view alone.
#include "scene/scene.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab {

// Problems reading or interpreting the file; the message starts with the file's path.
class GltfError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A loaded file: the mesh, whose triangleMaterials index `materials` (-1: the primitive named no
// material), the materials, whose texture indices index `textures`, and non-fatal notes.
struct GltfAsset {
    Mesh mesh;
    std::vector<Material> materials;   // named "materials[k]" or "materials[k] NAME"
    std::vector<Texture> textures;     // file: "srgb:" / "linear:" + FILE + "#textures[k]"
    std::vector<std::string> warnings; // each starts with the file's path
};

GltfAsset loadGltfAsset(const std::filesystem::path& file);
// Geometry only (loadGltfAsset's mesh without per-triangle materials).
Mesh loadGltf(const std::filesystem::path& file);

} // namespace raylab
