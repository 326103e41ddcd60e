// Exercise slab-test · level VWO 5-6 · about 40 minutes.
// Does a ray pass through an axis-aligned box, and where does it enter? (Kay & Kajiya 1986;
// pbrt-v4 §6.1.2, Bounds3::IntersectP; Ray Tracing: The Next Week §3.)
//
// The box is three slabs, boxMin.x ≤ x ≤ boxMax.x and so on. Along each axis the ray is inside
// its slab for t between (boxMin − origin)·invDir and (boxMax − origin)·invDir, in whichever
// order they come (a negative direction component swaps them). The ray is inside the box where it
// is inside all three slabs, and only for 0 ≤ t ≤ tMax. Return the entry t of that interval (0 when
// the origin is inside the box), or -1.0 when the interval is empty. invDir = 1/dir per component.
float intersectBox(vec3 origin, vec3 invDir, vec3 boxMin, vec3 boxMax, float tMax) {
    return 0.0;   // replace: every box is hit at t = 0
}
