// Exercise lambert · level VWO 5-6 · about 20 minutes.
// The BRDF of an ideally matte surface of albedo ρ. (pbrt-v4 §9.2, DiffuseBxDF; Ray Tracing in
// One Weekend: The Rest of Your Life §3.)
//
// A Lambertian surface scatters light equally in every direction above it: f(wo, wi) is one
// constant, chosen so that the reflected energy ∫ f cos θi dωi over the hemisphere equals ρ (the
// white furnace: a white surface, ρ = 1, reflects exactly all light). Return f, not f·cos θi:
// the renderer multiplies by the cosine itself. wo and wi are unit vectors in the local frame
// (+z the normal), both above the surface.
vec3 lambertBrdf(vec3 albedo, vec3 wo, vec3 wi) {
    return vec3(0.0);   // replace: a black surface
}
