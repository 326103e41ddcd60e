// Exercise cosine-hemisphere · level first-year university · about 45 minutes.
// Directions around +z with density cos θ / π, and that density. (pbrt-v4 §A.5.3, Malley's
// method; Ray Tracing in One Weekend: The Rest of Your Life §7.)
//
// sampleCosineHemisphere: turn two uniform numbers u in [0, 1)² into a unit vector with z > 0 whose
// density over solid angle is cos θ / π. Malley: pick a point uniformly on the unit disk (careful:
// a uniform radius is not uniform over the area), then lift it onto the hemisphere.
// pdfCosineHemisphere: the density of that direction given cos θ = its z (0 below the surface).
vec3 sampleCosineHemisphere(vec2 u) {
    return vec3(0.0, 0.0, 1.0);   // replace: always straight up
}

float pdfCosineHemisphere(float cosTheta) {
    return 1.0;   // replace
}
