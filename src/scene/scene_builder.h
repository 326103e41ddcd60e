#pragma once
// Validation: a parsed scene document -> Scene, key by key through the parameter tables
// (scene/parameters.h). The first problem is thrown as a ValidationFailure at its document path;
// the loader places it in the file or at the --set that caused it.
#include "scene/json_path.h"
#include "scene/parameters.h"
#include "scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::scenefmt {

// Fills `scene` (whose sourcePath is set: relative files are read from its directory) from `root`.
void buildScene(const Json& root, Scene& scene);

// One image texture of a material (path relative to `sceneDir`), loaded once per file and decoding
// into `textures`; sets the slot's file and index in `material`.
void readTextureSlot(const TextureSlot& slot, const Json& v, const JsonPath& p, const std::filesystem::path& sceneDir,
                     std::vector<Texture>& textures, Material& material);

// A key naming an image file: a non-empty string (fails at `p` otherwise).
std::string imageKey(const Json& v, const JsonPath& p);

// Tessellates and displaces `mesh` by `d` (mesh/displacement.h) from its shape as given (its
// displacement's source when it was displaced); without a texture the mesh stays as given. `p` is
// the object's path for errors; the mesh is unchanged when it throws.
void redisplaceMesh(Mesh& mesh, MeshDisplacement d, const JsonPath& p, const std::filesystem::path& sceneDir);

// camera.look_at must differ from camera.position, and camera.up must be a direction across the view.
void checkCamera(const Camera& camera);

// sky.map: a file name, relative to the scene file's directory; it must be an image whose pixels
// read (sky_map.h). sky.type "map" needs one.
void readSkyMap(const Json& root, Scene& scene);

} // namespace raylab::scenefmt
