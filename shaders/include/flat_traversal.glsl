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

// llvmpipe ends every loop of an invocation after 65535 iterations in all (path_tracer.glsl), which
// a one-triangle-per-iteration search of a large mesh exhausts; so with RAYLAB_FLAT_STEPS
// (estimator_stages.glsl) an iteration tests FLAT_TRIANGLES_PER_STEP triangles in index order, the
// hit and counts unchanged, and only then, as llvmpipe runs a loop body once even when no lane
// enters it (bench/mesh_rays.md).

#if RAYLAB_FEATURE_MESHES
#define RAYLAB_FLAT_TRIANGLE(k)                                                                       \
    if (!(found && anyHit)) {                                                                     \
        GpuTriangle tri = triangleAt(i + k);                                                      \
        RL_COUNT_TRIANGLE();                                                                      \
        TriangleHit h;                                                                            \
        if (intersectTriangle(triRay, xyzOf(tri.p0), xyzOf(tri.p1), xyzOf(tri.p2), rec.t - tOffset, h)) { \
            rec = TraceRecord(h.t + tOffset, instance, i + k, h.b1, h.b2);                        \
            found = true;                                                                         \
        }                                                                                         \
    }
// intersectTriangles (bvh_traversal.glsl) for a whole mesh: with RAYLAB_FLAT_STEPS whole steps of
// FLAT_TRIANGLES_PER_STEP triangles first, then the rest one at a time.
RL_FN bool intersectTrianglesFlat(TriangleRay triRay, float tOffset, uint instance, uint first, uint count,
                                  bool anyHit, RL_INOUT(TraceRecord) rec) {
    bool found = false;
    uint end = first + count;
    uint i = first;
#if RAYLAB_FLAT_STEPS
    for (; i + FLAT_TRIANGLES_PER_STEP <= end && !(found && anyHit); i += FLAT_TRIANGLES_PER_STEP) {
        RAYLAB_FLAT_TRIANGLE(0u) RAYLAB_FLAT_TRIANGLE(1u) RAYLAB_FLAT_TRIANGLE(2u) RAYLAB_FLAT_TRIANGLE(3u)
        RAYLAB_FLAT_TRIANGLE(4u) RAYLAB_FLAT_TRIANGLE(5u) RAYLAB_FLAT_TRIANGLE(6u) RAYLAB_FLAT_TRIANGLE(7u)
        RAYLAB_FLAT_TRIANGLE(8u) RAYLAB_FLAT_TRIANGLE(9u) RAYLAB_FLAT_TRIANGLE(10u) RAYLAB_FLAT_TRIANGLE(11u)
        RAYLAB_FLAT_TRIANGLE(12u) RAYLAB_FLAT_TRIANGLE(13u) RAYLAB_FLAT_TRIANGLE(14u) RAYLAB_FLAT_TRIANGLE(15u)
    }
#endif
    for (; i < end && !(found && anyHit); ++i) RAYLAB_FLAT_TRIANGLE(0u)
    return found;
}
#undef RAYLAB_FLAT_TRIANGLE
#ifdef __cplusplus
static_assert(FLAT_TRIANGLES_PER_STEP == 16u, "the loop above is written out for 16 triangles");
#endif
#endif

// Object i's primitives, all of them: a sphere, or every triangle of a mesh in its object space.
RL_FN bool intersectObjectPrimitives(Ray ray, uint i, bool anyHit, RL_INOUT(TraceRecord) rec) {
#if RAYLAB_FEATURE_MESHES
    GpuInstance inst = instanceAt(i);
    if (inst.info.x == INSTANCE_MESH) {
        float dt;
        Ray o = objectRay(inst, ray, dt);
        return dt < rec.t && intersectTrianglesFlat(triangleRay(o), dt, i, instanceFirstTriangle(inst),
                                                    instanceTriangleCount(inst), anyHit, rec);
    }
#endif
    return intersectInstance(ray, i, anyHit, rec);   // a sphere is its own only primitive
}

// Nearest hit in (0, tMax) (any hit with anyHit), like traceScene, which `leaving` is too;
// boxes: object boxes first.
RL_FN bool traceSceneFlat(Ray ray, float tMax, bool anyHit, bool boxes, uint leaving, RL_OUT(TraceRecord) rec) {
    rec = TraceRecord(tMax, 0u, 0u, 0.0f, 0.0f);
    vec3 invDir = safeInverseDir(ray.dir);
    bool found = false;
    uint count = instanceCount();
    for (uint i = 0u; i < count; ++i) {
        if (i == leaving) continue;
        if (boxes) {
            RL_COUNT_BOX();
            if (intersectBox(ray.origin, invDir, instanceWorldMin(i), instanceWorldMax(i), rec.t) < 0.0f) continue;
        }
        if (intersectObjectPrimitives(ray, i, anyHit, rec)) found = true;
        if (found && anyHit) break;
    }
    return found;
}

RL_FN bool traceSceneFlat(Ray ray, float tMax, bool anyHit, bool boxes, RL_OUT(TraceRecord) rec) {
    return traceSceneFlat(ray, tMax, anyHit, boxes, NO_INSTANCE, rec);
}

RL_NAMESPACE_END
#endif
