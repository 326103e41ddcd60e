// Exercise smith-g · level first-year university · about 40 minutes.
// Smith's masking function G1 for GGX: the fraction of microfacets facing w that w can see.
// (Heitz 2014, "Understanding the Masking-Shadowing Function", eq. 43 and 72; pbrt-v4 §9.6.3.)
//
// G1(w) = 2 / (1 + √(1 + α² tan²θ)), with θ the angle between the unit vector w and the normal
// +z. G1 is 1 looking straight down and falls to 0 at grazing angles. Return 0 for w at or below
// the horizon. The tracer builds the height-correlated G2 of a light path from your G1.
float ggxG1(vec3 w, float alpha) {
    return 1.0;   // replace: no masking at all
}
