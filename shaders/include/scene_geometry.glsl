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
#include "few_objects.glsl"

layout(std430, binding = BINDING_TOP_NODES) readonly buffer TopNodeBuffer { GpuBvhNode topNodes[]; };
layout(std430, binding = BINDING_MESH_NODES) readonly buffer MeshNodeBuffer { GpuBvhNode meshNodes[]; };
layout(std430, binding = BINDING_INSTANCES) readonly buffer InstanceBuffer { GpuInstance instances[]; };
layout(std430, binding = BINDING_TRIANGLES) readonly buffer TriangleBuffer { GpuTriangle triangles[]; };
layout(std430, binding = BINDING_VERTICES) readonly buffer VertexBuffer { GpuVertex vertices[]; };

// Traversal reads nodes, instances and triangles through integer texture buffers over the same GL
// buffers (bit-exact, RGBA32UI): on llvmpipe a texel fetch costs less than a per-lane vec4 load
// from a storage buffer (bench/mesh_rays.md), and on GPUs it is the usual cached read path for BVHs.
layout(binding = BINDING_TOP_NODE_TEXELS) uniform usamplerBuffer topNodeTexels;
layout(binding = BINDING_MESH_NODE_TEXELS) uniform usamplerBuffer meshNodeTexels;
layout(binding = BINDING_INSTANCE_TEXELS) uniform usamplerBuffer instanceTexels;
layout(binding = BINDING_TRIANGLE_TEXELS) uniform usamplerBuffer triangleTexels;
vec4 texelBits(usamplerBuffer b, uint i) { return uintBitsToFloat(texelFetch(b, int(i))); }
GpuBvhNode bvhNodeFrom(usamplerBuffer b, uint i) { return GpuBvhNode(texelBits(b, BVH_NODE_TEXELS * i), texelBits(b, BVH_NODE_TEXELS * i + 1u)); }
GpuBvhNode topNode(uint i) { return bvhNodeFrom(topNodeTexels, i); }
GpuBvhNode meshNode(uint i) { return bvhNodeFrom(meshNodeTexels, i); }
GpuInstance instanceAt(uint i) {
    uint b = INSTANCE_TEXELS * i;
    return GpuInstance(texelBits(instanceTexels, b), texelBits(instanceTexels, b + 1u), texelBits(instanceTexels, b + 2u),
                       texelBits(instanceTexels, b + 3u), texelBits(instanceTexels, b + 4u), texelBits(instanceTexels, b + 5u),
                       texelBits(instanceTexels, b + 6u), texelBits(instanceTexels, b + 7u), texelFetch(instanceTexels, int(b + 8u)));
}
GpuTriangle triangleAt(uint i) {
    uint b = TRIANGLE_TEXELS * i;
    return GpuTriangle(texelBits(triangleTexels, b), texelBits(triangleTexels, b + 1u), texelBits(triangleTexels, b + 2u),
                       texelFetch(triangleTexels, int(b + 3u)));
}
GpuVertex vertexAt(uint i) { return vertices[i]; }
GpuSphere sphereAt(uint i) { return spheres[i]; }
uint instanceCount() { return uint(instances.length()); }
uvec4 instanceInfo(uint i) { return instances[i].info; }
vec3 instanceWorldMin(uint i) { return instances[i].worldMin.xyz; }
vec3 instanceWorldMax(uint i) { return instances[i].worldMax.xyz; }
uvec2 instanceTriangleRange(uint i) { return floatBitsToUint(vec2(instances[i].worldMin.w, instances[i].worldMax.w)); }
uint sphereCount() { return uint(spheres.length()); }
#if RAYLAB_TOP_LEVEL_LINEAR
// Few objects' boxes and spheres (few_objects.glsl), read by the loops over them.
layout(std140, binding = BINDING_FEW_OBJECTS_UBO) uniform FewObjectsBlock {
    vec4 fewObjectMinBlock[FEW_OBJECTS_MAX];   // w: 1 for a mesh
    vec4 fewObjectMaxBlock[FEW_OBJECTS_MAX];
    GpuSphere fewSpheresBlock[FEW_OBJECTS_MAX];
    uvec4 fewObjectTrianglesBlock[FEW_OBJECTS_MAX];   // x first triangle, y count
};
#if RAYLAB_OBJECT_COUNT > 0
// The loops read the invocation's copy of the block, made before main runs (a global's
// initialiser), element by element so that the copies are values: llvmpipe (Mesa 22.3) reads a
// uniform block lane by lane with a bounds check per lane, even at a constant offset, where a
// private array read at a constant index is a register or a stack slot (bench/mesh_rays.md,
// "Uniform blocks copied once an invocation").
struct FewObjects {
    vec4 boxMin[RAYLAB_OBJECT_COUNT];
    vec4 boxMax[RAYLAB_OBJECT_COUNT];
    uvec2 triangles[RAYLAB_OBJECT_COUNT];
#if RAYLAB_SPHERE_COUNT > 0
    GpuSphere spheres[RAYLAB_SPHERE_COUNT];
#endif
};
FewObjects loadFewObjects() {
    FewObjects f;
    for (int i = 0; i < RAYLAB_OBJECT_COUNT; ++i) {
        f.boxMin[i] = fewObjectMinBlock[i];
        f.boxMax[i] = fewObjectMaxBlock[i];
        f.triangles[i] = fewObjectTrianglesBlock[i].xy;
    }
#if RAYLAB_SPHERE_COUNT > 0
    for (int k = 0; k < RAYLAB_SPHERE_COUNT; ++k)
        f.spheres[k] = GpuSphere(fewSpheresBlock[k].centerRadius, fewSpheresBlock[k].info);
#endif
    return f;
}
FewObjects fewObjects = loadFewObjects();
vec4 fewObjectMin(uint i) { return fewObjects.boxMin[i]; }   // w: 1 for a mesh
vec4 fewObjectMax(uint i) { return fewObjects.boxMax[i]; }
uvec2 fewObjectTriangles(uint i) { return fewObjects.triangles[i]; }   // first, count
#if RAYLAB_SPHERE_COUNT > 0
GpuSphere fewSphere(uint k) { return fewObjects.spheres[k]; }
#endif
#else
// Counts read at run time: the loops read the block itself.
vec4 fewObjectMin(uint i) { return fewObjectMinBlock[i]; }
vec4 fewObjectMax(uint i) { return fewObjectMaxBlock[i]; }
GpuSphere fewSphere(uint k) { return fewSpheresBlock[k]; }
#endif
bool fewObjectIsMesh(uint i) { return fewObjectMin(i).w != 0.0f; }
#endif

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
