float ggxG1(vec3 w, float alpha) {
    if (w.z <= 0.0) return 0.0;
    float k = alpha / 2.0;
    return w.z / (w.z * (1.0 - k) + k);
}
