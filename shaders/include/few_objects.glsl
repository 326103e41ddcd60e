// With few objects the tracer loops over them instead of walking the top-level BVH (features.glsl
// RAYLAB_TOP_LEVEL_LINEAR). Those loops read each object's world box, triangle range and each
// sphere from one uniform block, which every invocation copies once into private arrays that the
// unrolled loops (RAYLAB_OBJECT_COUNT) read at constant indices (scene_geometry.glsl fewObjects;
// bench/mesh_rays.md, "Few objects in a uniform block" and "Uniform blocks copied once an
// invocation"). C++ and GLSL.
#ifndef RAYLAB_FEW_OBJECTS_GLSL
#define RAYLAB_FEW_OBJECTS_GLSL
#include "compat.glsl"
#include "scene_types.glsl"
RL_NAMESPACE_BEGIN

// Up to this many objects (spheres and meshes) the top level is a plain loop (bench/geometry.md);
// the loop over meshes keeps a bit per object in a uint (bvh_traversal.glsl), so 32 at most.
const int FEW_OBJECTS_MAX = 16;

#ifdef __cplusplus
// The std140 uniform block of scene_geometry.glsl (render/few_objects.h fills it): objects in the
// top level's order, as the instance buffer holds them; entries past the scene's objects are 0.
struct FewObjectsBlock {
    vec4 boxMin[FEW_OBJECTS_MAX];         // the object's world box; w 1 for a mesh, 0 for a sphere
    vec4 boxMax[FEW_OBJECTS_MAX];
    GpuSphere spheres[FEW_OBJECTS_MAX];   // the spheres, as the sphere buffer holds them
    uvec4 triangles[FEW_OBJECTS_MAX];     // a mesh's triangles: x the first, y how many; 0 for a sphere
};
#endif

RL_NAMESPACE_END
#endif
