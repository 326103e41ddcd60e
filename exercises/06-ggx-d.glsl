// Exercise ggx-d · level first-year university · about 40 minutes.
// The GGX (Trowbridge–Reitz) distribution of microfacet normals. (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces", eq. 33; pbrt-v4 §9.6.1.)
//
// D(h) = α² / (π · cos⁴θ · (α² + tan²θ)²), with θ the angle between h and the normal +z and α the
// roughness width. h is a unit vector in the local frame. D is normalised over projected area:
// ∫ D(h) cos θ dω = 1 over the hemisphere. Return 0 for h at or below the horizon (cos θ ≤ 0).
float ggxD(vec3 h, float alpha) {
    return 1.0;   // replace
}
