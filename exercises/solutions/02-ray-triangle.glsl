// Exercise ray-triangle: a solution (Möller & Trumbore 1997).
bool intersectTriangle(Ray ray, vec3 p0, vec3 p1, vec3 p2, float tMax, out TriangleHit hit) {
    hit = TriangleHit(-1.0, 0.0, 0.0, 0.0);
    vec3 e1 = p1 - p0;
    vec3 e2 = p2 - p0;
    vec3 p = cross(ray.dir, e2);
    float det = dot(e1, p);
    if (det == 0.0) return false;
    float invDet = 1.0 / det;
    vec3 s = ray.origin - p0;
    float u = dot(s, p) * invDet;
    if (u < 0.0 || u > 1.0) return false;
    vec3 q = cross(s, e1);
    float v = dot(ray.dir, q) * invDet;
    if (v < 0.0 || u + v > 1.0) return false;
    float t = dot(e2, q) * invDet;
    if (!(t > 0.0 && t < tMax)) return false;
    hit = TriangleHit(t, 1.0 - u - v, u, v);
    return true;
}
