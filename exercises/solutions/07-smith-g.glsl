// Exercise smith-g: a solution (Heitz 2014, eq. 43 with Λ of eq. 72).
float ggxG1(vec3 w, float alpha) {
    if (w.z <= 0.0) return 0.0;
    float cos2 = w.z * w.z;
    float tan2 = (1.0 - cos2) / cos2;
    return 2.0 / (1.0 + sqrt(1.0 + alpha * alpha * tan2));
}
