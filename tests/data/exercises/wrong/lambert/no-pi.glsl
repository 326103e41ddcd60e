vec3 lambertBrdf(vec3 albedo, vec3 wo, vec3 wi) { return albedo; }
