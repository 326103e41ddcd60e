// GPU records of the acceleration structure, std430 and identical in C++ (vec4/uvec4 members
// only). Shared by C++ and GLSL. Buffers: scene_geometry.glsl (bindings 8–12).
#ifndef RAYLAB_GEOMETRY_TYPES_GLSL
#define RAYLAB_GEOMETRY_TYPES_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

// One BVH node, depth-first order: an interior node's first child follows it directly. The links
// ride in the bounds' w slots, so a node is 32 bytes read in two loads (pbrt-v4's LinearBVHNode
// size; on llvmpipe every component of a per-lane load costs a scalar load, bench/mesh_rays.md).
struct GpuBvhNode {
    vec4 boundsMin;   // xyz; w: bits of the link: leaf → first primitive, interior → second child
    vec4 boundsMax;   // xyz; w: bits of the kind: leaf → count << 3, interior → axis << 1 | 1
};
// A node of zeros is an empty leaf, so traversal ends at once for it. This matters on llvmpipe:
// in fragment shaders, lanes outside the triangle read zeros from buffers; with "count 0 =
// interior" those lanes looped until Mesa's loop limit, which also lost the live lanes' hits.
RL_FN uint bvhNodeLink(GpuBvhNode n) { return floatBitsToUint(n.boundsMin.w); }
RL_FN bool bvhNodeIsLeaf(GpuBvhNode n) { return (floatBitsToUint(n.boundsMax.w) & 1u) == 0u; }
RL_FN uint bvhNodeCount(GpuBvhNode n) { return floatBitsToUint(n.boundsMax.w) >> 3u; }
RL_FN uint bvhNodeAxis(GpuBvhNode n) { return (floatBitsToUint(n.boundsMax.w) >> 1u) & 3u; }
RL_FN GpuBvhNode bvhLeaf(vec3 lo, vec3 hi, uint first, uint count) {
    return GpuBvhNode(vec4(lo.x, lo.y, lo.z, uintBitsToFloat(first)), vec4(hi.x, hi.y, hi.z, uintBitsToFloat(count << 3u)));
}
RL_FN GpuBvhNode bvhInterior(vec3 lo, vec3 hi, uint secondChild, uint axis) {
    return GpuBvhNode(vec4(lo.x, lo.y, lo.z, uintBitsToFloat(secondChild)),
                      vec4(hi.x, hi.y, hi.z, uintBitsToFloat((axis << 1u) | 1u)));
}

const uint INSTANCE_SPHERE = 0u;
const uint INSTANCE_MESH = 1u;

// An object in the top-level BVH: a world-space sphere, or a mesh placed by an affine transform
// (rows of the 3×4 matrices; a sphere's are unused). Moving an object changes only this record
// and the top level. With RAYLAB_MESHES_IN_WORLD every mesh's rows are the identity's, and the
// tracer does not read them.
struct GpuInstance {
    vec4 worldToObject0;
    vec4 worldToObject1;
    vec4 worldToObject2;
    vec4 objectToWorld0;
    vec4 objectToWorld1;
    vec4 objectToWorld2;
    vec4 worldMin;   // xyz: the object's world-space box, as in the top level's leaves; w: bits of
                     // a mesh's first triangle (render.accel boxes and none test them all)
    vec4 worldMax;   // xyz; w: bits of the mesh's triangle count, 0 for a sphere
    uvec4 info;   // x: INSTANCE_SPHERE / INSTANCE_MESH; y: sphere index / mesh root node;
                  // z: material; w: the INSTANCE_HAS_* and INSTANCE_ESCAPES_* bits below, and
                  // from bit INSTANCE_OBJECT_ID_SHIFT up the object id (instanceObjectId)
};

// Bits of a GpuInstance's info.w.
const uint INSTANCE_HAS_NORMALS = 1u;   // a mesh with vertex normals (smooth shading)
const uint INSTANCE_HAS_UVS = 2u;
// A ray that leaves the object's surface on the front (the winding normal's side; a sphere's
// outside) or the back of the face it leaves never meets the object again (accel/escape_sides.h).
const uint INSTANCE_ESCAPES_FRONT = 4u;
const uint INSTANCE_ESCAPES_BACK = 8u;
const uint INSTANCE_OBJECT_ID_SHIFT = 4u;
// "No instance": the search leaves out none (traceScene's `leaving`).
const uint NO_INSTANCE = 0xffffffffu;

// Triangles a flat search (render.accel boxes and none, flat_traversal.glsl) tests per loop
// iteration; the host's draws are sized by the iterations that costs (PathTracer).
const uint FLAT_TRIANGLES_PER_STEP = 16u;

// Each record's size in 16-byte texels: the stride of its texture-buffer view (scene_geometry.glsl;
// render/gpu_scene.cpp checks them against sizeof).
const uint BVH_NODE_TEXELS = 2u;
const uint INSTANCE_TEXELS = 9u;
const uint TRIANGLE_TEXELS = 4u;

RL_FN uint instanceFirstTriangle(GpuInstance inst) { return floatBitsToUint(inst.worldMin.w); }
RL_FN uint instanceTriangleCount(GpuInstance inst) { return floatBitsToUint(inst.worldMax.w); }

// The scene's object number: sphere i is i, mesh j is sphereCount + j (Scene's order, the order
// sceneToJson writes "objects" in and the viewer's `objects.N` keys use).
RL_FN uint instanceObjectId(GpuInstance inst) { return inst.info.w >> INSTANCE_OBJECT_ID_SHIFT; }

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
