// The scene searched without the BVH (render.accel): boxes, the thesis's scheme (Fig. 5.2), tests
// every object's world box and, where the ray meets it, all of the object's primitives; none tests
// every primitive of the scene. Both find the BVH's hits (tests/accel/flat_traversal_test.cpp) at
// the cost the heat views and bench/estimator_stages.md show. Shared by C++ and GLSL: the includer
// defines the accessors of bvh_traversal.glsl; the instance record holds the object's world box and
// its mesh's triangles (geometry_types.glsl).
#ifndef RAYLAB_FLAT_TRAVERSAL_GLSL
#define RAYLAB_FLAT_TRAVERSAL_GLSL
#include "compat.glsl"
#include "bvh_traversal.glsl"
RL_NAMESPACE_BEGIN

// Object i's primitives, all of them: a sphere, or every triangle of a mesh in its object space.
RL_FN bool intersectObjectPrimitives(Ray ray, uint i, bool anyHit, RL_INOUT(TraceRecord) rec) {
#if RAYLAB_FEATURE_MESHES
    GpuInstance inst = instanceAt(i);
    if (inst.info.x == INSTANCE_MESH) {
        float dt;
        Ray o = objectRay(inst, ray, dt);
        return dt < rec.t && intersectTriangles(triangleRay(o), dt, i, instanceFirstTriangle(inst),
                                                instanceTriangleCount(inst), anyHit, rec);
    }
#endif
    return intersectInstance(ray, i, anyHit, rec);   // a sphere is its own only primitive
}

// Nearest hit in (0, tMax) (any hit with anyHit), like traceScene; boxes: object boxes first.
RL_FN bool traceSceneFlat(Ray ray, float tMax, bool anyHit, bool boxes, RL_OUT(TraceRecord) rec) {
    rec = TraceRecord(tMax, 0u, 0u, 0.0f, 0.0f);
    vec3 invDir = safeInverseDir(ray.dir);
    bool found = false;
    uint count = instanceCount();
    for (uint i = 0u; i < count; ++i) {
        if (boxes) {
            RL_COUNT_BOX();
            if (intersectBox(ray.origin, invDir, instanceWorldMin(i), instanceWorldMax(i), rec.t) < 0.0f) continue;
        }
        if (intersectObjectPrimitives(ray, i, anyHit, rec)) found = true;
        if (found && anyHit) break;
    }
    return found;
}

RL_NAMESPACE_END
#endif
