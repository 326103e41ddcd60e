float ggxD(vec3 h, float alpha) {
    if (h.z <= 0.0) return 0.0;
    float a2 = alpha * alpha;
    float cos2 = h.z * h.z;
    float tan2 = (1.0 - cos2) / cos2;
    float k = a2 + tan2;
    return a2 / (PI * cos2 * k * k);
}
