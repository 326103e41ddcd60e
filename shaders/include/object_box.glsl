// The flat list of objects that render.accel boxes and none search (flat_traversal.glsl): per
// top-level instance, its world box and its triangles, std430 and identical in C++. Shared by C++
// and GLSL. Buffer: scene_geometry.glsl (BINDING_OBJECT_BOXES).
#ifndef RAYLAB_OBJECT_BOX_GLSL
#define RAYLAB_OBJECT_BOX_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

struct GpuObjectBox {
    vec4 boundsMin;   // xyz: the object's world box, as the top level holds it; w unused
    vec4 boundsMax;
    uvec4 info;       // x: a mesh's first triangle, y: its triangle count (0 for a sphere); zw unused
};

RL_NAMESPACE_END
#endif
