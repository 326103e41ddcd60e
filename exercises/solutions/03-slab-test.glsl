// Exercise slab-test: a solution (Kay & Kajiya 1986, pbrt-v4 §6.1.2).
float intersectBox(vec3 origin, vec3 invDir, vec3 boxMin, vec3 boxMax, float tMax) {
    vec3 t0 = (boxMin - origin) * invDir;
    vec3 t1 = (boxMax - origin) * invDir;
    vec3 tNear = min(t0, t1);
    vec3 tFar = max(t0, t1);
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    float leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
    return enter <= leave ? enter : -1.0;
}
