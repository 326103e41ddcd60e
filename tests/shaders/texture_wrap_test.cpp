// Wrap modes of glTF samplers (shaders/include/texture.glsl on the CPU) and the ray cone's spread
// at bounces (shaders/include/ray_cone.glsl).
#include "texture/texture.h"

#include "texture/cpu_texels.h"
#include "shaders/include/ray_cone.glsl"
#include "shaders/include/texture.glsl"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab;
using namespace raylab::glsl;

namespace {

// A 4×1 ramp 0, 1, 2, 3 (one level only), with the given wrap modes.
GpuTexture ramp(std::vector<glm::vec4>& texels, TextureWrap u, TextureWrap v) {
    texels = {glm::vec4(0), glm::vec4(1), glm::vec4(2), glm::vec4(3)};
    cpuTexels = &texels;
    return GpuTexture(uvec4(0u, 4u, 1u, 1u | unsigned(u) << 16u | unsigned(v) << 24u));
}

} // namespace

TEST(TextureWrap, RepeatClampAndMirrorOutsideTheUnitSquare) {
    std::vector<glm::vec4> texels;
    // Texel centres are at u = 0.125, 0.375, 0.625, 0.875.
    const GpuTexture rep = ramp(texels, TextureWrap::Repeat, TextureWrap::Repeat);
    EXPECT_FLOAT_EQ(sampleTextureLevel(rep, 0, vec2(1.375f, 0.5f)).x, 1.0f);
    EXPECT_FLOAT_EQ(sampleTextureLevel(rep, 0, vec2(0.0f, 0.5f)).x, 1.5f) << "repeat blends across the edge (3 and 0)";
    const GpuTexture clampT = ramp(texels, TextureWrap::ClampToEdge, TextureWrap::Repeat);
    EXPECT_FLOAT_EQ(sampleTextureLevel(clampT, 0, vec2(1.375f, 0.5f)).x, 3.0f);
    EXPECT_FLOAT_EQ(sampleTextureLevel(clampT, 0, vec2(-2.0f, 0.5f)).x, 0.0f);
    EXPECT_FLOAT_EQ(sampleTextureLevel(clampT, 0, vec2(0.0f, 0.5f)).x, 0.0f) << "no blending with the far edge";
    EXPECT_FLOAT_EQ(sampleTextureLevel(clampT, 0, vec2(0.375f, 0.5f)).x, 1.0f) << "inside: unchanged";
    const GpuTexture mirror = ramp(texels, TextureWrap::MirroredRepeat, TextureWrap::Repeat);
    EXPECT_FLOAT_EQ(sampleTextureLevel(mirror, 0, vec2(1.375f, 0.5f)).x, 2.0f) << "1.375 folds back to 0.625";
    EXPECT_FLOAT_EQ(sampleTextureLevel(mirror, 0, vec2(-0.125f, 0.5f)).x, 0.0f) << "-0.125 folds to 0.125";
    EXPECT_FLOAT_EQ(sampleTextureLevel(mirror, 0, vec2(2.375f, 0.5f)).x, 1.0f) << "period 2";
    EXPECT_EQ(textureLevels(mirror), 1) << "the wrap bits do not leak into the level count";
    // v's mode is independent of u's: a 1×4 column.
    texels = {glm::vec4(0), glm::vec4(1), glm::vec4(2), glm::vec4(3)};
    const GpuTexture column(uvec4(0u, 1u, 4u, 1u | unsigned(TextureWrap::ClampToEdge) << 24u));
    EXPECT_FLOAT_EQ(sampleTextureLevel(column, 0, vec2(0.5f, 7.9f)).x, 3.0f);
    EXPECT_FLOAT_EQ(sampleTextureLevel(column, 0, vec2(7.9f, 0.375f)).x, 1.0f) << "u still repeats";
}

TEST(RayCone, SpreadGrowsAtRoughBouncesOnly) {
    EXPECT_EQ(rayConeBounceSpread(LOBE_SPECULAR, true, 0.0f), 0.0f) << "mirror";
    EXPECT_EQ(rayConeBounceSpread(LOBE_GLASS_TRANSMIT, true, 0.0f), 0.0f) << "smooth glass";
    EXPECT_EQ(rayConeBounceSpread(LOBE_NONE, false, 0.5f), 0.0f);
    EXPECT_FLOAT_EQ(rayConeBounceSpread(LOBE_DIFFUSE, false, 0.0f), 0.5f * float(M_PI));
    EXPECT_FLOAT_EQ(rayConeBounceSpread(LOBE_SPECULAR, false, 0.25f), 2.0f * std::atan(0.25f));
    EXPECT_FLOAT_EQ(rayConeBounceSpread(LOBE_SPECULAR, false, 1.0f), rayConeBounceSpread(LOBE_DIFFUSE, false, 0.0f))
        << "a diffuse bounce counts as GGX alpha 1";
    // Monotonic in alpha.
    float last = 0.0f;
    for (float a = 0.01f; a <= 1.0f; a += 0.01f) {
        const float b = rayConeBounceSpread(LOBE_SPECULAR, false, a);
        EXPECT_GT(b, last);
        last = b;
    }
}
