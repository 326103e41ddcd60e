#pragma once
// A scene's geometry in the GPU layout of shaders/include/geometry_types.glsl: per-mesh BVHs
// (built once per mesh, in object space) and a top-level BVH over the objects' world bounds.
// Moving objects only needs updateTopLevel, unless the meshes' transforms are baked into their
// vertices (meshesInWorld; render/baked_mesh_transforms.h): then a moved mesh is built again.
#include "accel/bvh.h"
#include "scene/scene.h"

#include "shaders/include/geometry_types.glsl"
#include "shaders/include/scene_types.glsl"

#include <vector>

namespace raylab {

struct SceneGeometry {
    // Bottom level: every mesh's nodes, triangles (in leaf order) and vertices, concatenated.
    std::vector<glsl::GpuBvhNode> meshNodes;
    std::vector<glsl::GpuTriangle> triangles;
    std::vector<glsl::GpuVertex> vertices;
    std::vector<std::uint32_t> meshRoot;   // per mesh: its root node in meshNodes
    std::vector<Aabb> meshBounds;          // per mesh: object-space bounds
    std::vector<glm::uvec2> meshTriangles; // per mesh: its first triangle in triangles and its count
    std::vector<unsigned> meshEscapeSides; // per mesh: INSTANCE_ESCAPES_* bits (accel/escape_sides.h)
    // The meshes' vertices are in world space, their transforms applied (GpuScene with
    // render/baked_mesh_transforms.h), and every instance is placed by the identity.
    bool meshesInWorld = false;
    // Top level.
    std::vector<glsl::GpuSphere> spheres;       // world space
    std::vector<glsl::GpuInstance> instances;   // in top-level leaf order
    std::vector<glsl::GpuBvhNode> topNodes;

    // Figures for benchmarks and reports.
    double meshBuildSeconds = 0.0;
    double topBuildSeconds = 0.0;
    double meshSahCost = 0.0;   // triangle-weighted mean of the mesh BVHs' SAH costs
    double topSahCost = 0.0;
    int maxDepth = 0;           // deepest of all BVHs
    std::size_t triangleCount() const { return triangles.size(); }
};

SceneGeometry buildSceneGeometry(const Scene& scene, const BvhOptions& options = {});
// Recomputes spheres, instances and the top level from the scene's objects and transforms;
// the meshes themselves (their count and data) must be unchanged.
void updateTopLevel(SceneGeometry& geometry, const Scene& scene, const BvhOptions& options = {});

// The axis-aligned box around the eight corners of `bounds` moved by `toWorld` (an empty box stays
// empty): a mesh instance's world box, as the top level holds it before its rounding slack.
Aabb transformedBounds(const Aabb& bounds, const glm::mat4& toWorld);

} // namespace raylab
