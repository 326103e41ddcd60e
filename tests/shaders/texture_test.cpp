// Texture filtering and ray-cone level of detail (shaders/include/texture.glsl on the CPU), and
// the mip pyramid (texture/texture.h).
#include "texture/texture.h"

#include "texture/cpu_texels.h"
#include "shaders/include/texture.glsl"

#include "accel/cpu_traversal.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

using namespace raylab;
using namespace raylab::glsl;

namespace {

// 8×8 texels in four uniform 4×4 quadrants: red, green (bottom), blue, white (top).
MipLevel quadrants() {
    MipLevel l;
    l.width = l.height = 8;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const glm::vec4 c = y < 4 ? (x < 4 ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 1, 0, 1))
                                      : (x < 4 ? glm::vec4(0, 0, 1, 1) : glm::vec4(1, 1, 1, 1));
            l.texels.push_back(c);
        }
    return l;
}

struct Uploaded {
    std::vector<glm::vec4> texels;
    GpuTexture record;
};

Uploaded upload(const std::vector<MipLevel>& levels) {
    Uploaded u;
    for (const MipLevel& l : levels) u.texels.insert(u.texels.end(), l.texels.begin(), l.texels.end());
    u.record = GpuTexture(uvec4(0u, unsigned(levels[0].width), unsigned(levels[0].height), unsigned(levels.size())));
    return u;
}

} // namespace

TEST(Texture, MipPyramidAveragesDownToOneTexel) {
    const std::vector<MipLevel> levels = buildMipPyramid(quadrants());
    ASSERT_EQ(levels.size(), 4u);   // 8, 4, 2, 1
    EXPECT_EQ(levels[2].width, 2);
    EXPECT_EQ(levels[2].texels[0], glm::vec4(1, 0, 0, 1)) << "each quadrant stays itself at 2×2";
    EXPECT_EQ(levels[3].texels[0], glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    // Odd sizes: a 3×1 image becomes 1×1, the mean of all three.
    MipLevel odd;
    odd.width = 3;
    odd.height = 1;
    odd.texels = {glm::vec4(0), glm::vec4(3), glm::vec4(6)};
    EXPECT_EQ(buildMipPyramid(odd).back().texels[0], glm::vec4(3));
}

TEST(Texture, BilinearIsExactAtTexelCentresWrapsAndBlendsBetweenLevels) {
    const Uploaded u = upload(buildMipPyramid(quadrants()));
    cpuTexels = &u.texels;
    EXPECT_EQ(sampleTexture(u.record, vec2(0.25f, 0.25f), 0.0f), vec4(1, 0, 0, 1));
    EXPECT_EQ(sampleTexture(u.record, vec2(0.75f, 0.25f), 0.0f), vec4(0, 1, 0, 1));
    EXPECT_EQ(sampleTexture(u.record, vec2(0.25f, 0.75f), 0.0f), vec4(0, 0, 1, 1));
    EXPECT_EQ(sampleTexture(u.record, vec2(1.75f, -0.25f), 0.0f), vec4(1, 1, 1, 1)) << "repeat";
    // Half-way between the centres of a red and a green texel.
    EXPECT_EQ(sampleTexture(u.record, vec2(0.5f, 0.25f), 0.0f), vec4(0.5f, 0.5f, 0, 1));
    // The last level is the mean; lod beyond it clamps; 2.5 mixes levels 2 and 3 half and half.
    EXPECT_EQ(sampleTexture(u.record, vec2(0.3f, 0.6f), 99.0f), vec4(0.5f, 0.5f, 0.5f, 1));
    EXPECT_EQ(sampleTexture(u.record, vec2(0.25f, 0.25f), 2.5f), vec4(0.75f, 0.25f, 0.25f, 1));
    cpuTexels = nullptr;
}

TEST(Texture, RayConeLevelGrowsWithDistanceAndGrazingAngle) {
    // A 2×2-unit quad with uv [0, 1]² facing +z, hit head-on from distance d by a pixel cone of
    // spread α: width α·d, so the level rises by exactly 1 per doubling of the distance.
    const Scene scene = parseScene(R"({ "objects": [ { "type": "mesh",
        "positions": [-1,-1,0, 1,-1,0, 1,1,0, -1,1,0], "indices": [0,1,2, 0,2,3],
        "uvs": [0,0, 1,0, 1,1, 0,1] } ] })", "quad.json");
    const SceneGeometry g = buildSceneGeometry(scene);
    cpuTraversal.geometry = &g;
    const GpuTexture tex(uvec4(0u, 1024u, 1024u, 11u));
    const float spread = 1e-3f;
    auto lodAt = [&](float d, vec3 dir) {
        const Ray ray(vec3(0.1f, 0.2f, 0.0f) - d * dir, dir);
        TraceRecord rec{};
        EXPECT_TRUE(traceScene(ray, FLOAT_MAX, false, rec));
        const SurfaceHit s = surfaceAt(ray, rec);
        return rayConeLod(tex, s.lodBase, spread * rec.t, dot(s.normal, ray.dir));
    };
    const vec3 head(0, 0, -1);
    const float l1 = lodAt(1.0f, head), l2 = lodAt(2.0f, head), l8 = lodAt(8.0f, head);
    // Texel footprint: 1024 texels over 2 units; cone width 1e-3 at d = 1 covers 0.512 texels.
    EXPECT_NEAR(l1, std::log2(0.512f), 1e-4f);
    EXPECT_NEAR(l2 - l1, 1.0f, 1e-4f);
    EXPECT_NEAR(l8 - l1, 3.0f, 1e-4f);
    // At 60° from the normal the footprint stretches by 1/cos = 2: one level more.
    const vec3 tilted = normalize(vec3(std::sin(PI / 3), 0.0f, -std::cos(PI / 3)));
    EXPECT_NEAR(lodAt(1.0f, tilted) - l1, 1.0f, 1e-3f);
    cpuTraversal.geometry = nullptr;
}
