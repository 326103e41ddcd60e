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
    // Meshes tessellated and displaced on loading (scene.h MeshDisplacement):
    std::size_t displacedMeshes = 0;
    std::size_t displacedTrianglesBefore = 0;   // their triangles as given
    std::size_t displacedTriangles = 0;         // after subdivision
    double displacementMs = 0.0;                // the time it took, on loading
};

SceneStats sceneStats(const Scene& scene, const SceneGeometry& geometry);
// Two lines for reports: "objects ... | BVH ... | textures ... | lights ...", and a third with the
// displacement's cost when some mesh is displaced.
std::string describeSceneStats(const SceneStats& stats);
// "scene: displacement: 2 meshes, 4 -> 1024 triangles, 1.2 ms on loading".
std::string describeDisplacement(const SceneStats& stats);
// 1536 → "1.5 KiB".
std::string formatBytes(std::size_t bytes);

} // namespace raylab
