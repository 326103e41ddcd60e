// Exercise schlick · level VWO 5-6 · about 25 minutes.
// Schlick's approximation of Fresnel reflectance for a microfacet. (Schlick 1994, "An Inexpensive
// BRDF Model for Physically-based Rendering", eq. 15; pbrt-v4 §9.3; Filament §4.4.)
//
// Light comes from wi and leaves towards wo (unit vectors); it is reflected by the microfacet
// whose normal is the halfway vector h = normalize(wo + wi). With cos θ = wi·h (equal to wo·h):
// F = f0 + (f90 − f0)·(1 − cos θ)⁵. f0 is the reflectance head-on, f90 at grazing (1 in Schlick's
// original). Return F per colour channel.
vec3 schlickFresnel(vec3 f0, float f90, vec3 wo, vec3 wi) {
    return f0;   // replace: the same at every angle
}
