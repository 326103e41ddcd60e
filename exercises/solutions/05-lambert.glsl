// Exercise lambert: a solution (pbrt-v4 §9.2).
vec3 lambertBrdf(vec3 albedo, vec3 wo, vec3 wi) { return albedo / PI; }
