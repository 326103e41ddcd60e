#pragma once
// The GPU's traversals (shaders/include/bvh_traversal.glsl, flat_traversal.glsl) run on the CPU over a
// SceneGeometry: the reference for tests and a way to inspect traversal without a GPU.
// Not thread-safe: one current geometry per thread.
#include "accel/scene_geometry.h"

#include <cstdint>

namespace raylab::glsl {

struct CpuTraversalState {
    const SceneGeometry* geometry = nullptr;
    std::uint64_t boxTests = 0;
    std::uint64_t triangleTests = 0;
};
inline thread_local CpuTraversalState cpuTraversal;

inline GpuBvhNode topNode(uint i) { return cpuTraversal.geometry->topNodes[i]; }
inline GpuBvhNode meshNode(uint i) { return cpuTraversal.geometry->meshNodes[i]; }
inline GpuInstance instanceAt(uint i) { return cpuTraversal.geometry->instances[i]; }
inline GpuTriangle triangleAt(uint i) { return cpuTraversal.geometry->triangles[i]; }
inline GpuVertex vertexAt(uint i) { return cpuTraversal.geometry->vertices[i]; }
inline GpuSphere sphereAt(uint i) { return cpuTraversal.geometry->spheres[i]; }
inline uint instanceCount() { return uint(cpuTraversal.geometry->instances.size()); }
inline uvec4 instanceInfo(uint i) { return cpuTraversal.geometry->instances[i].info; }
inline vec3 instanceWorldMin(uint i) { return vec3(cpuTraversal.geometry->instances[i].worldMin); }
inline vec3 instanceWorldMax(uint i) { return vec3(cpuTraversal.geometry->instances[i].worldMax); }
inline uvec2 instanceTriangleRange(uint i) {
    const GpuInstance& inst = cpuTraversal.geometry->instances[i];
    return uvec2(instanceFirstTriangle(inst), instanceTriangleCount(inst));
}
inline uint sphereCount() { return uint(cpuTraversal.geometry->spheres.size()); }

} // namespace raylab::glsl

#define RL_COUNT_BOX() (++::raylab::glsl::cpuTraversal.boxTests)
#define RL_COUNT_TRIANGLE() (++::raylab::glsl::cpuTraversal.triangleTests)
#include "shaders/include/bvh_traversal.glsl"
#include "shaders/include/flat_traversal.glsl"
