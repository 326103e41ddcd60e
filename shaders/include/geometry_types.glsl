// GPU records of the acceleration structure, std430 and identical in C++ (vec4/uvec4 members
// only). Shared by C++ and GLSL. Buffers: scene_geometry.glsl (bindings 8–12).
#ifndef RAYLAB_GEOMETRY_TYPES_GLSL
#define RAYLAB_GEOMETRY_TYPES_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

// One BVH node, depth-first order: an interior node's first child follows it directly.
struct GpuBvhNode {
    vec4 boundsMin;   // xyz; w unused
    vec4 boundsMax;   // xyz; w unused
    uvec4 info;       // x: leaf → first primitive, interior → second child; y: primitive count
                      // (leaf); z: split axis (interior); w: 1 = interior, 0 = leaf
};
// A node of zeros is an empty leaf, so traversal ends at once for it. This matters on llvmpipe:
// in fragment shaders, lanes outside the triangle read zeros from buffers; with "count 0 =
// interior" those lanes looped until Mesa's loop limit, which also lost the live lanes' hits.

const uint INSTANCE_SPHERE = 0u;
const uint INSTANCE_MESH = 1u;

// An object in the top-level BVH: a world-space sphere, or a mesh placed by an affine transform
// (rows of the 3×4 matrices). Moving an object changes only this record and the top level.
struct GpuInstance {
    vec4 worldToObject0;
    vec4 worldToObject1;
    vec4 worldToObject2;
    vec4 objectToWorld0;
    vec4 objectToWorld1;
    vec4 objectToWorld2;
    uvec4 info;   // x: INSTANCE_SPHERE / INSTANCE_MESH; y: sphere index / mesh root node;
                  // z: material; w: bit 0 = has vertex normals, bit 1 = has uvs, bits 2+ = the
                  // object id (instanceObjectId)
};

// The scene's object number: sphere i is i, mesh j is sphereCount + j (Scene's order, the order
// sceneToJson writes "objects" in and the viewer's `objects.N` keys use).
RL_FN uint instanceObjectId(GpuInstance inst) { return inst.info.w >> 2u; }

// A triangle in its mesh's BVH leaf order. It carries its own object-space positions, so a
// triangle test reads one record instead of an index record and three vertices.
struct GpuTriangle {
    vec4 p0;          // xyz: position of vertex 0 (object space); w unused
    vec4 p1;
    vec4 p2;
    uvec4 vertices;   // xyz: indices into the vertex buffer; w: material + 1, 0 = the instance's
};

struct GpuVertex {
    vec4 positionU;   // xyz object-space position, w texture u
    vec4 normalV;     // xyz object-space shading normal (0 when none), w texture v
};

RL_NAMESPACE_END
#endif
