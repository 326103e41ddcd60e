// Exercise ggx-d: a solution (Walter et al. 2007, eq. 33, in the α² / (π (cos²θ(α² − 1) + 1)²) form).
float ggxD(vec3 h, float alpha) {
    if (h.z <= 0.0) return 0.0;
    float a2 = alpha * alpha;
    float k = h.z * h.z * (a2 - 1.0) + 1.0;
    return a2 / (PI * k * k);
}
