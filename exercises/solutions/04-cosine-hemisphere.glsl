// Exercise cosine-hemisphere: a solution (polar disk map, then Malley's lift).
vec3 sampleCosineHemisphere(vec2 u) {
    float r = sqrt(u.x);
    float phi = 2.0 * PI * u.y;
    vec2 d = r * vec2(cos(phi), sin(phi));
    return vec3(d, sqrt(max(0.0, 1.0 - dot(d, d))));
}

float pdfCosineHemisphere(float cosTheta) { return max(cosTheta, 0.0) / PI; }
