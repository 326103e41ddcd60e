// Exercise ray-sphere: a solution (the textbook quadratic, Ray Tracing in One Weekend §6).
float intersectSphere(Ray ray, vec3 center, float radius, float tMin, float tMax) {
    vec3 oc = ray.origin - center;
    float halfB = dot(oc, ray.dir);
    float c = dot(oc, oc) - radius * radius;
    float disc = halfB * halfB - c;
    if (disc < 0.0) return -1.0;
    float s = sqrt(disc);
    float t = -halfB - s;
    if (t > tMin && t < tMax) return t;
    t = -halfB + s;
    if (t > tMin && t < tMax) return t;
    return -1.0;
}
