float intersectSphere(Ray ray, vec3 center, float radius, float tMin, float tMax) {
    vec3 oc = ray.origin - center
    return -1.0;
}
