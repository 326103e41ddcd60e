float intersectBox(vec3 origin, vec3 invDir, vec3 boxMin, vec3 boxMax, float tMax) {
    vec3 tNear = (boxMin - origin) * invDir;
    vec3 tFar = (boxMax - origin) * invDir;
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    float leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
    return enter <= leave ? enter : -1.0;
}
