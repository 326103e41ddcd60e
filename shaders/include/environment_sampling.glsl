// Importance sampling of the sky map by the piecewise-constant tables that
// render/environment_distribution.cpp builds (keep the two in step). GLSL only.
#ifndef RAYLAB_ENVIRONMENT_SAMPLING_GLSL
#define RAYLAB_ENVIRONMENT_SAMPLING_GLSL
#include "compat.glsl"
#include "environment_map.glsl"
#include "scene_data.glsl"

#if RAYLAB_SKY_MAP   // the tables exist only with a sky map
// The last index i in [0, n) with cdf[offset + i] <= u (cdf[offset + n] is 1).
int envFindMarginal(int n, float u) {
    int lo = 0;
    int hi = n;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (envMarginalCdf[mid] <= u) lo = mid;
        else hi = mid;
    }
    return lo;
}

int envFindConditional(int offset, int n, float u) {
    int lo = 0;
    int hi = n;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (envConditionalCdf[offset + mid] <= u) lo = mid;
        else hi = mid;
    }
    return lo;
}
#endif

// Density over (u, v) of the texel a direction falls in: weight / mean weight, where the weight
// is max(r, g, b) × sinθ of the texel's row (EnvironmentDistribution::texelWeight).
float envPdfUv(ivec2 texel, ivec2 size) {
    vec3 c = texelFetch(uSkyMap, texel, 0).rgb;
    float theta = (float(texel.y) + 0.5f) / float(size.y) * PI;
    return max(max(c.r, c.g), max(c.b, 0.0f)) * sin(theta) / params.envMeanWeight;
}

// Solid-angle density: pdf(u, v) / (2π² sinθ), the Jacobian of the equirectangular map.
float environmentPdf(vec3 dir) {
    ivec2 size = textureSize(uSkyMap, 0);
    vec2 uv = equirectFromDirection(dir, params.skyRotation);
    float sinTheta = sin(uv.y * PI);
    if (sinTheta <= 0.0f || params.envMeanWeight <= 0.0f) return 0.0f;
    ivec2 texel = min(ivec2(uv * vec2(size)), size - ivec2(1));
    return envPdfUv(texel, size) / (2.0f * PI * PI * sinTheta);
}

// A direction from the map's distribution, with the solid-angle density of the texel it was
// drawn in (exact, whereas re-mapping the direction may land in a neighbour at a texel edge),
// and the image coordinates it came from.
#if RAYLAB_SKY_MAP
vec3 sampleEnvironment(vec2 u, out float pdf, out vec2 uvOut) {
    ivec2 size = textureSize(uSkyMap, 0);
    int y = envFindMarginal(size.y, u.y);
    int offset = y * (size.x + 1);
    int x = envFindConditional(offset, size.x, u.x);
    float y0 = envMarginalCdf[y];
    float dy = envMarginalCdf[y + 1] - y0;
    float x0 = envConditionalCdf[offset + x];
    float dx = envConditionalCdf[offset + x + 1] - x0;
    float fy = dy > 0.0f ? clamp((u.y - y0) / dy, 0.0f, 0.99999994f) : 0.5f;
    float fx = dx > 0.0f ? clamp((u.x - x0) / dx, 0.0f, 0.99999994f) : 0.5f;
    vec2 uv = vec2((float(x) + fx) / float(size.x), (float(y) + fy) / float(size.y));
    float sinTheta = sin(uv.y * PI);
    pdf = sinTheta > 0.0f ? envPdfUv(ivec2(x, y), size) / (2.0f * PI * PI * sinTheta) : 0.0f;
    uvOut = uv;
    return directionFromEquirect(uv, params.skyRotation);
}
#else
// Without a sky map nothing samples it (skyByMap() is false): a stub keeps the callers compiling.
vec3 sampleEnvironment(vec2 u, out float pdf, out vec2 uvOut) {
    pdf = 0.0f;
    uvOut = u;
    return vec3(0.0f, 1.0f, 0.0f);
}
#endif

#endif
