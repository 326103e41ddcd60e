float intersectSphere(Ray ray, vec3 center, float radius, float tMin, float tMax) {
    vec3 oc = ray.origin - center;
    float halfB = dot(oc, ray.dir);
    float disc = halfB * halfB - (dot(oc, oc) - radius * radius);
    if (disc < 0.0) return -1.0;
    float t = -halfB - sqrt(disc);
    if (t < tMax) return t;
    t = -halfB + sqrt(disc);
    return t < tMax ? t : -1.0;
}
