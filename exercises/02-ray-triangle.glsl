// Exercise ray-triangle · level first-year university · about 60 minutes.
// Möller–Trumbore: where does a ray meet the triangle p0 p1 p2? (Möller & Trumbore 1997,
// "Fast, Minimum Storage Ray/Triangle Intersection"; Shirley & Marschner, Fundamentals of
// Computer Graphics §4.4.2.)
//
// Write the hit point as p0 + u·(p1 − p0) + v·(p2 − p0) = ray.origin + t·ray.dir and solve for
// (t, u, v) with Cramer's rule. It is a hit when u ≥ 0, v ≥ 0, u + v ≤ 1 (an edge counts: two
// triangles that share it must not leave a crack) and 0 < t < tMax. Both sides of the triangle
// count. On a hit, fill hit = TriangleHit(t, 1 − u − v, u, v) and return true; else return false.
bool intersectTriangle(Ray ray, vec3 p0, vec3 p1, vec3 p2, float tMax, out TriangleHit hit) {
    hit = TriangleHit(-1.0, 0.0, 0.0, 0.0);
    return false;   // replace: no triangle is ever hit
}
