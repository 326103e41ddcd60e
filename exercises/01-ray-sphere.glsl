// Exercise ray-sphere · level VWO 5-6 · about 45 minutes.
// Where does a ray first meet a sphere? (Ray Tracing in One Weekend §6; pbrt-v4 §6.2.2.)
//
// The ray is p(t) = ray.origin + t·ray.dir, with |ray.dir| = 1. The sphere is every p with
// |p − center|² = radius². Substitute p(t): a quadratic a·t² + b·t + c = 0. Return the smallest
// root t with tMin < t < tMax (if the nearer root is at or below tMin, the camera may be inside the
// sphere: then the farther root counts), or -1.0 when the ray misses in that range.
float intersectSphere(Ray ray, vec3 center, float radius, float tMin, float tMax) {
    return -1.0;   // replace: no sphere is ever hit
}
