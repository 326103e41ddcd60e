vec3 sampleCosineHemisphere(vec2 u) {
    float z = u.x;
    float r = sqrt(max(0.0, 1.0 - z * z));
    float phi = 2.0 * PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}
float pdfCosineHemisphere(float cosTheta) { return max(cosTheta, 0.0) / PI; }
