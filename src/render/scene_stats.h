#pragma once
// Scene statistics for the viewer's Stats panel and raylab-render's report: what a scene holds
// and what its acceleration structure and textures cost. Computed from the scene and its built
// geometry alone (no GL), so a test checks them against a known scene.
#include "accel/scene_geometry.h"
#include "scene/scene.h"

#include <cstddef>
#include <string>

namespace raylab {

struct SceneStats {
    std::size_t objects = 0;         // spheres + mesh instances
    std::size_t spheres = 0;
    std::size_t instances = 0;       // mesh objects (each places one mesh with its transform)
    std::size_t triangles = 0;       // over all meshes
    std::size_t vertices = 0;
    std::size_t materials = 0;
    std::size_t topBvhNodes = 0;     // the BVH over the objects
    std::size_t meshBvhNodes = 0;    // all meshes' BVHs together
    int bvhDepth = 0;                // the deepest of all BVHs, in edges
    std::size_t textures = 0;        // material textures (albedo, normal maps)
    std::size_t textureBytes = 0;    // their texel and table buffers on the GPU, all mip levels
    // The lights of next-event estimation's list (render/light_list.h):
    std::size_t emissiveSpheres = 0;     // spheres with an emissive material
    std::size_t emissiveTriangles = 0;   // triangles with an emissive material (their own or the mesh's) and area
    std::size_t analyticLights = 0;      // point, spot and distant lights that emit
};

SceneStats sceneStats(const Scene& scene, const SceneGeometry& geometry);
// Two lines for reports: "objects ... | BVH ... | textures ... | lights ...".
std::string describeSceneStats(const SceneStats& stats);
// 1536 → "1.5 KiB".
std::string formatBytes(std::size_t bytes);

} // namespace raylab
