// Exercise schlick: a solution (Schlick 1994, eq. 15).
vec3 schlickFresnel(vec3 f0, float f90, vec3 wo, vec3 wi) {
    vec3 h = normalize(wo + wi);
    float c = clamp(dot(wi, h), 0.0, 1.0);
    return f0 + (vec3(f90) - f0) * pow(1.0 - c, 5.0);
}
