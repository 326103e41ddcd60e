float ggxG1(vec3 w, float alpha) {
    if (w.z <= 0.0) return 0.0;
    float tan2 = (1.0 - w.z * w.z) / (w.z * w.z);
    return 2.0 / (1.0 + sqrt(1.0 + alpha * tan2));
}
