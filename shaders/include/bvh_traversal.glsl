// Two-level BVH traversal: a top-level BVH over objects (world-space spheres and mesh instances),
// each mesh with its own BVH in object space. Nearest child first with a small stack (pbrt-v4
// BVHAggregate::Intersect), any-hit early exit for shadow rays. Shared by C++ and GLSL: the
// includer first defines the accessors
//   GpuBvhNode topNode(uint i); GpuBvhNode meshNode(uint i); GpuInstance instanceAt(uint i);
//   GpuTriangle triangleAt(uint i); GpuVertex vertexAt(uint i); GpuSphere sphereAt(uint i);
//   uint instanceCount(); uvec4 instanceInfo(uint i); vec3 instanceWorldMin(uint i);
//   vec3 instanceWorldMax(uint i); uvec2 instanceTriangleRange(uint i) (first, count); uint sphereCount();
// (GLSL: scene_geometry.glsl reads buffers; C++: accel/cpu_traversal.h reads vectors), and may
// define RL_COUNT_BOX() / RL_COUNT_TRIANGLE() to count tests (heat maps).
#ifndef RAYLAB_BVH_TRAVERSAL_GLSL
#define RAYLAB_BVH_TRAVERSAL_GLSL
#include "compat.glsl"
#include "features.glsl"
#include "ray.glsl"
#include "aabb.glsl"
#include "sphere.glsl"
#include "triangle.glsl"
#include "instance_transform.glsl"
#include "scene_types.glsl"
#include "geometry_types.glsl"
#ifndef RL_COUNT_BOX
#define RL_COUNT_BOX()
#endif
#ifndef RL_COUNT_TRIANGLE
#define RL_COUNT_TRIANGLE()
#endif
RL_NAMESPACE_BEGIN

// Depth bound of both levels: the builder splits at the median below depth 40 (accel/bvh.h).
const int BVH_STACK_SIZE = 64;

// What traversal found: enough to build the surface record afterwards (scene_surface.glsl).
struct TraceRecord {
    float t;
    uint instance;
    uint primitive;   // sphere index, or triangle index (global)
    float b1;         // barycentrics of the triangle's second and third vertex
    float b2;
};

RL_FN vec3 nodeMin(GpuBvhNode n) { return vec3(n.boundsMin.x, n.boundsMin.y, n.boundsMin.z); }
RL_FN vec3 nodeMax(GpuBvhNode n) { return vec3(n.boundsMax.x, n.boundsMax.y, n.boundsMax.z); }

#if RAYLAB_FEATURE_MESHES
// Nearest of triangles [first, first + count) in (0, rec.t), in object space; updates rec.
RL_FN bool intersectTriangles(TriangleRay triRay, float tOffset, uint instance, uint first, uint count, bool anyHit,
                              RL_INOUT(TraceRecord) rec) {
    bool found = false;
    for (uint i = first; i < first + count; ++i) {
        GpuTriangle tri = triangleAt(i);
        RL_COUNT_TRIANGLE();
        TriangleHit h;
        if (intersectTriangle(triRay, xyzOf(tri.p0), xyzOf(tri.p1), xyzOf(tri.p2), rec.t - tOffset, h)) {
            rec = TraceRecord(h.t + tOffset, instance, i, h.b1, h.b2);
            found = true;
            if (anyHit) break;
        }
    }
    return found;
}

// Nearest triangle of one mesh in (0, rec.t), in the mesh's object space; updates rec. The
// object-space ray starts tOffset further along than the world ray (see objectRay). An inner node
// tests both children's boxes in one step and goes on into the nearer one, keeping the other if
// the ray meets it (Aila & Laine 2009, "Understanding the Efficiency of Ray Traversal on GPUs"):
// a missed child then costs no step of its own, and a step's loop control and stack work, which
// llvmpipe runs masked for all eight lanes, are spent once per two boxes (bench/mesh_rays.md).
RL_FN bool traverseMesh(Ray ray, float tOffset, uint instance, uint root, bool anyHit, RL_INOUT(TraceRecord) rec) {
    vec3 invDir = safeInverseDir(ray.dir);
    TriangleRay triRay = triangleRay(ray);
    bool found = false;
    uint stack[BVH_STACK_SIZE];
    int sp = 0;
    uint node = root;
    GpuBvhNode n = meshNode(node);   // the node of the step; the ray meets its box
    RL_COUNT_BOX();
    if (intersectBox(ray.origin, invDir, nodeMin(n), nodeMax(n), rec.t - tOffset) < 0.0f) return false;
    bool done = false;
    while (!done) {
        bool pop = true;
        if (bvhNodeIsLeaf(n)) {
            if (intersectTriangles(triRay, tOffset, instance, bvhNodeLink(n), bvhNodeCount(n), anyHit, rec)) found = true;
            done = found && anyHit;
        } else {
            uint a = node + 1u;
            uint b = bvhNodeLink(n);
            GpuBvhNode na = meshNode(a);
            GpuBvhNode nb = meshNode(b);
            RL_COUNT_BOX();
            RL_COUNT_BOX();
            float ta = intersectBox(ray.origin, invDir, nodeMin(na), nodeMax(na), rec.t - tOffset);
            float tb = intersectBox(ray.origin, invDir, nodeMin(nb), nodeMax(nb), rec.t - tOffset);
            if (ta >= 0.0f || tb >= 0.0f) {
                // Nearer entry first; a child the ray misses has t = -1.
                bool aFirst = tb < 0.0f || (ta >= 0.0f && ta <= tb);
                if (ta >= 0.0f && tb >= 0.0f && sp < BVH_STACK_SIZE) stack[sp++] = aFirst ? b : a;
                node = aFirst ? a : b;
                n = aFirst ? na : nb;
                pop = false;
            }
        }
        if (pop && !done) {
            if (sp == 0) done = true;
            else {
                node = stack[--sp];
                n = meshNode(node);
            }
        }
    }
    return found;
}

// A mesh instance's ray in its object space; the direction is not renormalised, so t carries over.
// The transformed origin is only known within its rounding error: it is moved forward along the
// ray to the edge of that error box, by dt, so a surface the world ray starts on is not met again,
// and the interval is shortened by as much (pbrt-v4 Transform::operator()(Ray), §6.8.6).
RL_FN Ray objectRay(GpuInstance inst, Ray ray, RL_OUT(float) dt) {
#if RAYLAB_MESHES_IN_WORLD
    dt = 0.0f;   // placed by the identity: object space is world space, nothing is rounded
    return ray;
#else
    vec3 o = transformPoint(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2, ray.origin);
    vec3 d = transformVector(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2, ray.dir);
    vec3 oError = transformPointError(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2, ray.origin,
                                      vec3(0.0f));
    dt = dot(abs(d), oError) / dot(d, d);
    return Ray(o + dt * d, d);
#endif
}
#endif

// One object of the top level: a world-space sphere, or a mesh traversed in its object space.
RL_FN bool intersectInstance(Ray ray, uint i, bool anyHit, RL_INOUT(TraceRecord) rec) {
    bool found = false;
    GpuInstance inst = instanceAt(i);
#if RAYLAB_FEATURE_SPHERES
    if (inst.info.x == INSTANCE_SPHERE) {
        GpuSphere s = sphereAt(inst.info.y);
        float t = intersectSphere(ray, xyzOf(s.centerRadius), s.centerRadius.w, 0.0f, rec.t);
        if (t > 0.0f) {
            rec = TraceRecord(t, i, inst.info.y, 0.0f, 0.0f);
            found = true;
        }
    }
#endif
#if RAYLAB_FEATURE_MESHES
    if (inst.info.x == INSTANCE_MESH) {
        float dt;
        Ray o = objectRay(inst, ray, dt);
        if (dt < rec.t && traverseMesh(o, dt, i, inst.info.y, anyHit, rec)) found = true;
    }
#endif
    return found;
}

// Nearest hit of the scene in (0, tMax); with anyHit, stops at the first hit found. `leaving`: an
// instance the ray leaves outwards and so cannot meet (accel/escape_sides.h), left out of the
// search, or NO_INSTANCE.
RL_FN bool traceScene(Ray ray, float tMax, bool anyHit, uint leaving, RL_OUT(TraceRecord) rec) {
    rec = TraceRecord(tMax, 0u, 0u, 0.0f, 0.0f);
    bool found = false;
#if RAYLAB_TOP_LEVEL_LINEAR
    // Few objects: plain loops beat the top-level traversal's stack and box tests (measured in
    // bench/geometry.md). Their trip counts are the scene's (RAYLAB_OBJECT_COUNT), and they read
    // the spheres and boxes by the loop counter from the invocation's copy of the few-objects
    // block (scene_geometry.glsl): one value for all lanes.
#if RAYLAB_FEATURE_SPHERES
#if RAYLAB_OBJECT_COUNT > 0
    const uint sphereTotal = uint(RAYLAB_SPHERE_COUNT);
#else
    uint sphereTotal = sphereCount();
#endif
    for (uint k = 0u; k < sphereTotal; ++k) {
        GpuSphere s = fewSphere(k);   // not left out when leaving: that branch costs more than the test (bench/mesh_rays.md)
        float t = intersectSphere(ray, xyzOf(s.centerRadius), s.centerRadius.w, 0.0f, rec.t);
        if (t > 0.0f) {
            rec = TraceRecord(t, s.info.y, k, 0.0f, 0.0f);
            found = true;
            if (anyHit) return true;
        }
    }
#endif
#if RAYLAB_FEATURE_MESHES
    // The object's world box first: it spares a ray the per-lane reads of the mesh's records for
    // every object it passes by.
    vec3 invDir = safeInverseDir(ray.dir);
#if RAYLAB_OBJECT_COUNT > 0
    const uint count = uint(RAYLAB_OBJECT_COUNT);
#else
    uint count = instanceCount();
#endif
#if RAYLAB_MESHES_IN_WORLD && !RAYLAB_COUNT_TRAVERSAL
    // Every mesh in world space: the ray is sheared for the triangle test once. Each lane notes
    // the objects whose boxes its ray meets, then tests their triangles in one loop, so an object
    // costs only the lanes that meet it: SIMD lanes run an object loop's every branch together
    // (bench/mesh_rays.md, "A ray does not search the object it leaves").
    TriangleRay triRay = triangleRay(ray);
    uint pending = 0u;   // bit i: instance i's box is met (FEW_OBJECTS_MAX <= 32)
    for (uint i = 0u; i < count; ++i) {
        if (!fewObjectIsMesh(i) || i == leaving) continue;
        if (intersectBox(ray.origin, invDir, fewObjectMin(i).xyz, fewObjectMax(i).xyz, rec.t) >= 0.0f) pending |= 1u << i;
    }
    uint instance = 0u;
    uint next = 0u;   // the lane's next triangle, and the end of its object's
    uint end = 0u;
    while (pending != 0u || next < end) {
        if (next == end) {
            instance = uint(findLSB(pending));
            pending &= pending - 1u;
#if RAYLAB_OBJECT_COUNT > 0
            // The lanes' objects differ: a select per object from the copy, where the instance
            // record would be a texel gather.
            uvec2 range = uvec2(0u);
            for (uint i = 0u; i < count; ++i) range = instance == i ? fewObjectTriangles(i) : range;
            next = range.x;
            end = range.x + range.y;
#else
            GpuInstance inst = instanceAt(instance);   // only the triangle range is read
            next = instanceFirstTriangle(inst);
            end = next + instanceTriangleCount(inst);
#endif
        }
        if (next < end) {
            GpuTriangle tri = triangleAt(next);
            TriangleHit h;
            if (intersectTriangle(triRay, xyzOf(tri.p0), xyzOf(tri.p1), xyzOf(tri.p2), rec.t, h)) {
                rec = TraceRecord(h.t, instance, next, h.b1, h.b2);
                found = true;
                if (anyHit) break;
            }
            ++next;
        }
    }
#else
    for (uint i = 0u; i < count; ++i) {
        if (!fewObjectIsMesh(i) || i == leaving) continue;
        RL_COUNT_BOX();
        if (intersectBox(ray.origin, invDir, fewObjectMin(i).xyz, fewObjectMax(i).xyz, rec.t) < 0.0f) continue;
#if RAYLAB_SMALL_MESHES && !RAYLAB_COUNT_TRAVERSAL
        // A few triangles: tested straight after the world box, without the mesh BVH's root read,
        // box test and walk (bench/mesh_rays.md). The heat views count the BVH's own tests.
        GpuInstance inst = instanceAt(i);
        float dt;
        Ray o = objectRay(inst, ray, dt);
        if (dt < rec.t && intersectTriangles(triangleRay(o), dt, i, instanceFirstTriangle(inst), instanceTriangleCount(inst),
                                             anyHit, rec))
            found = true;
#else
        if (intersectInstance(ray, i, anyHit, rec)) found = true;
#endif
        if (found && anyHit) break;
    }
#endif
#endif
    return found;
#else
    vec3 invDir = safeInverseDir(ray.dir);
    uint stack[BVH_STACK_SIZE];
    int sp = 0;
    uint node = 0u;
    bool done = false;
    while (!done) {
        GpuBvhNode n = topNode(node);
        RL_COUNT_BOX();
        bool descended = false;
        if (intersectBox(ray.origin, invDir, nodeMin(n), nodeMax(n), rec.t) >= 0.0f) {
            if (bvhNodeIsLeaf(n)) {
                uint first = bvhNodeLink(n);
                for (uint i = first; i < first + bvhNodeCount(n); ++i) {
                    if (i != leaving && intersectInstance(ray, i, anyHit, rec)) found = true;
                    if (found && anyHit) break;
                }
                if (found && anyHit) done = true;
            } else {
                bool dirNeg = ray.dir[int(bvhNodeAxis(n))] < 0.0f;
                uint first = node + 1u;
                uint second = bvhNodeLink(n);
                if (sp < BVH_STACK_SIZE) stack[sp++] = dirNeg ? first : second;
                node = dirNeg ? second : first;
                descended = true;
            }
        }
        if (!descended && !done) {
            if (sp == 0) done = true;
            else node = stack[--sp];
        }
    }
    return found;
#endif
}

RL_FN bool traceScene(Ray ray, float tMax, bool anyHit, RL_OUT(TraceRecord) rec) {
    return traceScene(ray, tMax, anyHit, NO_INSTANCE, rec);
}

// Is anything in (0, tMax) along the ray? For shadow rays: tMax is the light's distance (in units
// of |dir|), so a light's own surface should lie beyond the interval.
RL_FN bool occludedBvh(Ray ray, float tMax) {
    TraceRecord rec;
    return traceScene(ray, tMax, true, rec);
}

// The surface at a record: position from barycentrics (triangles) or re-projected (spheres),
// with its error bound; geometric normal (unit, pointing out of a sphere / along e01 × e02 of a
// triangle); shading normal (interpolated vertex normals, else the geometric one); uv.
struct SurfaceHit {
    vec3 position;
    vec3 normal;
    vec3 shadingNormal;
    vec3 error;
    vec2 uv;
    uint material;
    float lodBase;   // ½·log2(uv area / world area) around the hit, for ray-cone texture LOD
    vec3 tangent;    // ∂p/∂u in world space (normal maps' tangent frame); 0 where undefined
    uint escapes;    // the object's INSTANCE_ESCAPES_* bits (accel/escape_sides.h)
};

RL_FN SurfaceHit surfaceAt(Ray ray, TraceRecord rec) {
    SurfaceHit s;
    s.lodBase = 0.0f;
    s.tangent = vec3(0.0f);
    s.escapes = INSTANCE_ESCAPES_FRONT;   // a sphere's
#if RAYLAB_FEATURE_SPHERES
    // A sphere's material is in its own record: without meshes the instance record is not read at
    // all (that per-lane read cost 2892 → 1811 instructions per path on the default scene,
    // bench/throughput.md).
#if RAYLAB_FEATURE_MESHES
    if (instanceInfo(rec.instance).x == INSTANCE_SPHERE) {
#else
    {
#endif
        GpuSphere sp = sphereAt(rec.primitive);
        s.material = sp.info.x;
        vec3 c = xyzOf(sp.centerRadius);
        float r = sp.centerRadius.w;
        s.position = sphereSurfacePoint(rayAt(ray, rec.t), c, r);
        s.normal = normalize(s.position - c);
        s.shadingNormal = s.normal;
        s.error = sphereHitError(c, r);
        // Equirectangular uv: u around +y from +x, v from the bottom pole.
        s.uv = vec2(0.0f);
#if RAYLAB_FEATURE_TEXTURES   // uv and its footprint only where something reads them
        s.uv = vec2(0.5f + atan(s.normal.z, s.normal.x) * (0.5f * INV_PI),
                    acos(clamp(-s.normal.y, -1.0f, 1.0f)) * INV_PI);
        // du·dv = dθ·dφ / (2π²) against dA = r²·sinθ·dθ·dφ.
        float sinTheta = max(sqrt(max(0.0f, 1.0f - s.normal.y * s.normal.y)), 1e-6f);
        s.lodBase = 0.5f * log2(1.0f / (2.0f * PI * PI * r * r * sinTheta));
        s.tangent = vec3(-s.normal.z, 0.0f, s.normal.x);   // direction of growing u (longitude)
#endif
        return s;
    }
#endif
#if RAYLAB_FEATURE_MESHES
    GpuInstance inst = instanceAt(rec.instance);   // with RAYLAB_MESHES_IN_WORLD only info is read
    s.material = inst.info.z;
    s.escapes = inst.info.w & (INSTANCE_ESCAPES_FRONT | INSTANCE_ESCAPES_BACK);
    GpuTriangle tri = triangleAt(rec.primitive);
    GpuVertex v0 = vertexAt(tri.vertices.x);
    GpuVertex v1 = vertexAt(tri.vertices.y);
    GpuVertex v2 = vertexAt(tri.vertices.z);
    if (tri.vertices.w != 0u) s.material = tri.vertices.w - 1u;   // per-triangle material (glTF)
    vec3 p0 = xyzOf(tri.p0);
    vec3 p1 = xyzOf(tri.p1);
    vec3 p2 = xyzOf(tri.p2);
    TriangleHit h = TriangleHit(rec.t, 1.0f - rec.b1 - rec.b2, rec.b1, rec.b2);
    vec3 pObj = triangleHitPoint(h, p0, p1, p2);
    vec3 eObj = triangleHitError(h, p0, p1, p2);
#if RAYLAB_MESHES_IN_WORLD
    // Placed by the identity: the object-space point, its error and normal are the world's.
    s.position = pObj;
    s.error = eObj;
    s.normal = normalize(cross(p1 - p0, p2 - p0));
#else
    s.position = transformPoint(inst.objectToWorld0, inst.objectToWorld1, inst.objectToWorld2, pObj);
    // A ray leaving this point is transformed back into object space (intersectInstance), which
    // rounds its origin again; the bound includes that error too, so the offset clears both.
    vec3 eBack = transformPointError(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2, s.position,
                                     vec3(0.0f));
    s.error = transformPointError(inst.objectToWorld0, inst.objectToWorld1, inst.objectToWorld2, pObj, eObj + eBack);
    s.normal = normalize(transformNormal(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2,
                                         cross(p1 - p0, p2 - p0)));
#endif
    s.shadingNormal = s.normal;
#if RAYLAB_FEATURE_SMOOTH_NORMALS
    if ((inst.info.w & INSTANCE_HAS_NORMALS) != 0u) {
        vec3 n = h.b0 * xyzOf(v0.normalV) + h.b1 * xyzOf(v1.normalV) + h.b2 * xyzOf(v2.normalV);
#if RAYLAB_MESHES_IN_WORLD
        vec3 nw = n;
#else
        vec3 nw = transformNormal(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2, n);
#endif
        if (dot(nw, nw) > 0.0f) s.shadingNormal = normalize(nw);
    }
#endif
    vec2 t0 = vec2(v0.positionU.w, v0.normalV.w);
    vec2 t1 = vec2(v1.positionU.w, v1.normalV.w);
    vec2 t2 = vec2(v2.positionU.w, v2.normalV.w);
    s.uv = h.b0 * t0 + h.b1 * t1 + h.b2 * t2;
#if RAYLAB_FEATURE_TEXTURES
    // Ray Tracing Gems ch. 20, eq. 34: texel-to-world area ratio of the triangle (world edges).
#if RAYLAB_MESHES_IN_WORLD
    vec3 w1 = p1 - p0;
    vec3 w2 = p2 - p0;
#else
    vec3 w1 = transformVector(inst.objectToWorld0, inst.objectToWorld1, inst.objectToWorld2, p1 - p0);
    vec3 w2 = transformVector(inst.objectToWorld0, inst.objectToWorld1, inst.objectToWorld2, p2 - p0);
#endif
    float uvArea = abs((t1.x - t0.x) * (t2.y - t0.y) - (t2.x - t0.x) * (t1.y - t0.y));
    s.lodBase = 0.5f * log2(max(uvArea, 1e-30f) / max(length(cross(w1, w2)), 1e-30f));
    // ∂p/∂u from the uv differences of the edges (pbrt-v4 Triangle::InteractionFromIntersection).
    vec2 duv1 = t1 - t0;
    vec2 duv2 = t2 - t0;
    float uvDet = duv1.x * duv2.y - duv1.y * duv2.x;
    if (uvDet != 0.0f) s.tangent = (duv2.y * w1 - duv1.y * w2) / uvDet;
#endif
#endif
    return s;
}

RL_NAMESPACE_END
#endif
