// Image textures: bilinear filtering between texel centres, wrap (repeat) addressing, and
// trilinear mip filtering at a level of detail from ray cones (Akenine-Möller et al., "Texture
// Level of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20, 2019, §20.3.4).
// Shared by C++ and GLSL: the includer defines `vec4 texelAt(uint i)` (GLSL: scene_textures.glsl).
#ifndef RAYLAB_TEXTURE_GLSL
#define RAYLAB_TEXTURE_GLSL
#include "compat.glsl"
#include "features.glsl"
RL_NAMESPACE_BEGIN

// One texture: its level 0 starts at texel `offset`; the levels follow each other, level l is
// max(1, width >> l) × max(1, height >> l).
struct GpuTexture {
    uvec4 info;   // x offset, y width, z height, w levels | wrap u << 16 | wrap v << 24
};

// Wrap modes (glTF samplers; scene-file textures repeat). Compiled in only where some texture of
// the scene does not repeat (RAYLAB_TEXTURE_WRAP_MODES; always in C++).
const uint TEXTURE_WRAP_REPEAT = 0u;
const uint TEXTURE_WRAP_CLAMP = 1u;
const uint TEXTURE_WRAP_MIRROR = 2u;

RL_FN int textureLevels(GpuTexture t) { return int(t.info.w & 0xffffu); }

#if RAYLAB_TEXTURE_WRAP_MODES
RL_FN uint textureWrapU(GpuTexture t) { return (t.info.w >> 16u) & 0xffu; }
RL_FN uint textureWrapV(GpuTexture t) { return (t.info.w >> 24u) & 0xffu; }
// A coordinate into [0, 1]: repeat takes the fraction, clamp clips, mirror folds every other
// period back (period 2: 1.25 → 0.75).
RL_FN float wrapCoordinate(float c, uint mode) {
    if (mode == TEXTURE_WRAP_CLAMP) return clamp(c, 0.0f, 1.0f);
    if (mode == TEXTURE_WRAP_MIRROR) return 1.0f - abs(2.0f * (0.5f * c - floor(0.5f * c)) - 1.0f);
    return c - floor(c);
}
// Bilinear taps just outside the image: the neighbour across the edge when repeating, else the
// edge texel itself (clamp; mirror reflects at the edge, which is the same texel).
RL_FN int wrapIndexMode(int i, int n, uint mode) {
    if (mode == TEXTURE_WRAP_REPEAT) return i < 0 ? i + n : (i >= n ? i - n : i);
    return clamp(i, 0, n - 1);
}
#endif

// i in [-1, n]: uv is wrapped into [0, 1) first, so bilinear taps stay within one step.
RL_FN int wrapIndex(int i, int n) { return i < 0 ? i + n : (i >= n ? i - n : i); }

RL_FN vec4 textureLevelTexel(uint base, int w, int h, int x, int y) {
    return texelAt(base + uint(wrapIndex(y, h) * w + wrapIndex(x, w)));
}

// Bilinear sample of one level; uv outside [0, 1) follows the texture's wrap modes.
RL_FN vec4 sampleTextureLevel(GpuTexture t, int level, vec2 uv) {
    uint base = t.info.x;
    int w = int(t.info.y);
    int h = int(t.info.z);
    for (int l = 0; l < level; ++l) {
        base += uint(w * h);
        w = max(1, w / 2);
        h = max(1, h / 2);
    }
#if RAYLAB_TEXTURE_WRAP_MODES
    uint wrapU = textureWrapU(t);
    uint wrapV = textureWrapV(t);
    if (wrapU != TEXTURE_WRAP_REPEAT || wrapV != TEXTURE_WRAP_REPEAT) {
        float gx = wrapCoordinate(uv.x, wrapU) * float(w) - 0.5f;
        float gy = wrapCoordinate(uv.y, wrapV) * float(h) - 0.5f;
        int jx = int(floor(gx));
        int jy = int(floor(gy));
        float bx = gx - floor(gx);
        float by = gy - floor(gy);
        int x0w = wrapIndexMode(jx, w, wrapU);
        int x1w = wrapIndexMode(jx + 1, w, wrapU);
        int y0w = wrapIndexMode(jy, h, wrapV);
        int y1w = wrapIndexMode(jy + 1, h, wrapV);
        vec4 c = mix(texelAt(base + uint(y0w * w + x0w)), texelAt(base + uint(y0w * w + x1w)), bx);
        vec4 d = mix(texelAt(base + uint(y1w * w + x0w)), texelAt(base + uint(y1w * w + x1w)), bx);
        return mix(c, d, by);
    }
#endif
    float fx = (uv.x - floor(uv.x)) * float(w) - 0.5f;
    float fy = (uv.y - floor(uv.y)) * float(h) - 0.5f;
    float x0 = floor(fx);
    float y0 = floor(fy);
    float ax = fx - x0;
    float ay = fy - y0;
    int ix = int(x0);
    int iy = int(y0);
    vec4 a = mix(textureLevelTexel(base, w, h, ix, iy), textureLevelTexel(base, w, h, ix + 1, iy), ax);
    vec4 b = mix(textureLevelTexel(base, w, h, ix, iy + 1), textureLevelTexel(base, w, h, ix + 1, iy + 1), ax);
    return mix(a, b, ay);
}

// Trilinear: lod 0 is the full image; each +1 halves the resolution.
RL_FN vec4 sampleTexture(GpuTexture t, vec2 uv, float lod) {
    int levels = textureLevels(t);
    float l = clamp(lod, 0.0f, float(levels) - 1.0f);
    int l0 = int(floor(l));
    int l1 = min(l0 + 1, levels - 1);
    float f = l - float(l0);
    vec4 a = sampleTextureLevel(t, l0, uv);
    if (f <= 0.0f || l1 == l0) return a;
    return mix(a, sampleTextureLevel(t, l1, uv), f);
}

// Ray-cone level of detail (eq. 34 of the chapter): λ = Δ + log2|W| − log2|n̂·d̂|, with
// Δ = ½·log2(texel area / world area) of the hit triangle (uv area × width × height over its
// world-space area; lodBase below is ½·log2(uv area / world area)), W the cone's width at the hit.
RL_FN float rayConeLod(GpuTexture t, float lodBase, float coneWidth, float cosine) {
    float texels = float(t.info.y) * float(t.info.z);
    return lodBase + 0.5f * log2(texels) + log2(max(abs(coneWidth), 1e-30f)) - log2(max(abs(cosine), 1e-4f));
}

RL_NAMESPACE_END
#endif
