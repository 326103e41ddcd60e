float ggxD(vec3 h, float alpha) {
    if (h.z <= 0.0) return 0.0;
    float k = h.z * h.z * (alpha - 1.0) + 1.0;
    return alpha / (PI * k * k);
}
