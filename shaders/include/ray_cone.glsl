// How a ray cone's spread angle changes at a bounce, for texture level of detail along whole
// paths. Shared by C++ and GLSL.
//
// Akenine-Möller et al., "Texture Level of Detail Strategies for Real-Time Ray Tracing", Ray
// Tracing Gems ch. 20 (2019), §20.3.4: a cone has a width W and a spread angle γ; over a segment
// of length t the width grows as W_i = W_{i-1} + γ_{i-1}·t_i, and at the i-th hit the spread angle
// changes as γ_i = γ_{i-1} + β_i (eq. 32), where the chapter takes β from the surface's curvature
// for (mirror) reflections. Its rough- and diffuse-surface case is left open; here β is the angular
// width of the lobe the path was scattered into: a GGX lobe of width α spreads the microfacet
// normals by about atan(α) on each side of the mean, and reflection doubles angles, so
// β = 2·atan(α); a diffuse bounce counts as α = 1 (β = π/2); delta lobes (mirror, smooth glass)
// add nothing (surfaces are taken as flat: no curvature term).
#ifndef RAYLAB_RAY_CONE_GLSL
#define RAYLAB_RAY_CONE_GLSL
#include "compat.glsl"
#include "bsdf_sample.glsl"
RL_NAMESPACE_BEGIN

// β: the increase of the spread angle (radians) after a bounce into `lobe` (LOBE_*), not delta,
// of GGX width alpha (ignored for diffuse).
RL_FN float rayConeBounceSpread(int lobe, bool delta, float alpha) {
    if (lobe == LOBE_NONE || delta) return 0.0f;
    if (lobe == LOBE_DIFFUSE) return 0.5f * PI;
    return 2.0f * atan(min(alpha, 1.0f));
}

RL_NAMESPACE_END
#endif
