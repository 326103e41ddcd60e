// The host contract for geometry (render/gpu_scene.cpp) and the accessors the
// shared traversal (bvh_traversal.glsl) reads through. GLSL only.
// Optional define RAYLAB_COUNT_TRAVERSAL: every box and triangle test is counted per invocation
// (gBoxTests, gTriangleTests) and summed into the TraversalCounters buffer (heat-map views).
#ifndef RAYLAB_SCENE_GEOMETRY_GLSL
#define RAYLAB_SCENE_GEOMETRY_GLSL
#include "scene_types.glsl"
#include "geometry_types.glsl"
#include "scene_data.glsl"
#include "estimator_stages.glsl"

layout(std430, binding = BINDING_TOP_NODES) readonly buffer TopNodeBuffer { GpuBvhNode topNodes[]; };
layout(std430, binding = BINDING_MESH_NODES) readonly buffer MeshNodeBuffer { GpuBvhNode meshNodes[]; };
layout(std430, binding = BINDING_INSTANCES) readonly buffer InstanceBuffer { GpuInstance instances[]; };
layout(std430, binding = BINDING_TRIANGLES) readonly buffer TriangleBuffer { GpuTriangle triangles[]; };
layout(std430, binding = BINDING_VERTICES) readonly buffer VertexBuffer { GpuVertex vertices[]; };

GpuBvhNode topNode(uint i) { return topNodes[i]; }
GpuBvhNode meshNode(uint i) { return meshNodes[i]; }
GpuInstance instanceAt(uint i) { return instances[i]; }
GpuTriangle triangleAt(uint i) { return triangles[i]; }
GpuVertex vertexAt(uint i) { return vertices[i]; }
GpuSphere sphereAt(uint i) { return spheres[i]; }
uint instanceCount() { return uint(instances.length()); }
uvec4 instanceInfo(uint i) { return instances[i].info; }
vec3 instanceWorldMin(uint i) { return instances[i].worldMin.xyz; }
vec3 instanceWorldMax(uint i) { return instances[i].worldMax.xyz; }
uint sphereCount() { return uint(spheres.length()); }

#if RAYLAB_COUNT_TRAVERSAL
layout(std430, binding = BINDING_TRAVERSAL_COUNTERS) buffer TraversalCounters {
    uint boxTestsTotal;
    uint triangleTestsTotal;
};
uint gBoxTests = 0u;
uint gTriangleTests = 0u;
#define RL_COUNT_BOX() (++gBoxTests)
#define RL_COUNT_TRIANGLE() (++gTriangleTests)
#endif

#endif
