// Warps from the unit square to directions and points, each with its pdf.
#ifndef RAYLAB_SAMPLING_GLSL
#define RAYLAB_SAMPLING_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

// Concentric square-to-disk map (Shirley & Chiu 1997; pbrt-v4 SampleUniformDiskConcentric):
// uniform on the unit disk, keeps strata, no fold at the centre.
RL_FN vec2 sampleDiskConcentric(vec2 u) {
    vec2 o = 2.0f * u - vec2(1.0f);
    if (o.x == 0.0f && o.y == 0.0f) return vec2(0.0f);
    float r;
    float theta;
    if (abs(o.x) > abs(o.y)) {
        r = o.x;
        theta = (PI / 4.0f) * (o.y / o.x);
    } else {
        r = o.y;
        theta = (PI / 2.0f) - (PI / 4.0f) * (o.x / o.y);
    }
    return r * vec2(cos(theta), sin(theta));
}

// Cosine-weighted hemisphere around +z by Malley's method: pdf = cos θ / π.
// With a Lambertian BRDF ρ/π the sample weight f·cos/pdf is exactly ρ.
// On the disk's rim (u exactly 0, or cos² + sin² rounding to 1) z would be 0: pdf 0, a sample the
// integrator must drop. z is kept at least 2^-18, above the rounding of a
// frame change (~1e-7), so the direction stays on its side; the weight f·cos/pdf uses this z too.
#ifdef RAYLAB_EXERCISE_COSINE_HEMISPHERE
#include RAYLAB_EXERCISE_COSINE_HEMISPHERE   // a pupil's sampleCosineHemisphere and pdfCosineHemisphere
#else
RL_FN vec3 sampleCosineHemisphere(vec2 u) {
    vec2 d = sampleDiskConcentric(u);
    float z = sqrt(max(3.8146973e-6f * 3.8146973e-6f, 1.0f - d.x * d.x - d.y * d.y));
    return vec3(d.x, d.y, z);
}

RL_FN float pdfCosineHemisphere(float cosTheta) { return max(cosTheta, 0.0f) * INV_PI; }
#endif

// Uniform hemisphere around +z (pbrt-v4 SampleUniformHemisphere): z = 1 − u.x is never 0, so the
// direction stays above the surface; pdf = 1/(2π) (render.diffuse_sampling uniform).
RL_FN vec3 sampleUniformHemisphere(vec2 u) {
    float z = 1.0f - u.x;
    float r = sqrt(max(0.0f, 1.0f - z * z));
    float phi = 2.0f * PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

RL_FN float pdfUniformHemisphere(float cosTheta) { return cosTheta > 0.0f ? 0.5f * INV_PI : 0.0f; }

RL_NAMESPACE_END
#endif
