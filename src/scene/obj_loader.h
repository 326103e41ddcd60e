#pragma once
// Wavefront OBJ files → Mesh (positions, per-vertex normals and uvs, triangles), through
// tinyobjloader. Polygons are triangulated; vertices that share position, normal and uv indices
// are merged. Materials (.mtl) are not read: the scene assigns the material.
#include "scene/scene.h"

#include <filesystem>
#include <stdexcept>

namespace raylab {

// Problems reading or interpreting the file; the message starts with the file's path.
class ObjError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Fills positions, normals, uvs and triangles of a Mesh (file, material, transform untouched).
Mesh loadObj(const std::filesystem::path& file);

} // namespace raylab
