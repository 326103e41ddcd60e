#pragma once
// glTF 2.0 files (.gltf with external or embedded buffers, .glb) → one Mesh, through tinygltf:
// every triangle primitive of the default scene (or the first scene), with the node hierarchy's
// transforms applied to positions and normals; POSITION, NORMAL and TEXCOORD_0 attributes;
// 8-, 16- and 32-bit indices. Not read (yet): glTF materials and textures (the scene's material
// applies to the whole mesh), animations, skins, morph targets, sparse accessors.
#include "scene/scene.h"

#include <filesystem>
#include <stdexcept>

namespace raylab {

// Problems reading or interpreting the file; the message starts with the file's path.
class GltfError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

Mesh loadGltf(const std::filesystem::path& file);

} // namespace raylab
