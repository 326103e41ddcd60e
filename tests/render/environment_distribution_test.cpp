// Importance sampling of sky maps (render/environment_distribution.h): χ² of the texel counts
// against the distribution's own pdf, uniformity inside texels, black texels never chosen.
#include "render/environment_distribution.h"
#include "shaders/include/random.glsl"
#include "support/statistics.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab;

namespace {

Image testMap() {
    // 24 × 12 texels: smooth variation, a bright "sun" texel, a black column and a black row.
    Image img(24, 12);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 24; ++x) {
            float v = 0.2f + 0.1f * float((x * 7 + y * 3) % 5);
            if (x == 5) v = 0.0f;
            if (y == 9) v = 0.0f;
            if (x == 17 && y == 3) v = 50.0f;
            const size_t i = size_t(y * 24 + x) * 4;
            img.rgba[i] = v;
            img.rgba[i + 1] = 0.5f * v;
            img.rgba[i + 2] = 0.25f * v;
            img.rgba[i + 3] = 1.0f;
        }
    return img;
}

} // namespace

TEST(EnvironmentDistribution, SamplesFollowThePdfAndAreUniformInsideTexels) {
    const Image map = testMap();
    const EnvironmentDistribution dist(map);
    const int w = map.width, h = map.height, n = 1000000;
    // Cells: each texel split 2 × 2, so uniformity inside texels is tested too.
    std::vector<double> observed(size_t(w * h * 4), 0.0), expected(size_t(w * h * 4), 0.0);
    double integral = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float p = dist.pdfUv(glm::vec2((float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h)));
            integral += double(p) / (double(w) * h);
            for (int k = 0; k < 4; ++k) expected[size_t((y * w + x) * 4 + k)] = n * double(p) / (double(w) * h) / 4.0;
        }
    EXPECT_NEAR(integral, 1.0, 1e-5);
    glsl::Rng rng = glsl::rngCreate(glm::uvec2(3, 3), 0u, 3u);
    int inconsistent = 0;
    for (int i = 0; i < n; ++i) {
        float pdf = 0.0f;
        const glm::vec2 uv = dist.sample(glsl::rngNext2(rng), pdf);
        ASSERT_GE(uv.x, 0.0f);
        ASSERT_LT(uv.x, 1.0f);
        ASSERT_GE(uv.y, 0.0f);
        ASSERT_LT(uv.y, 1.0f);
        if (std::abs(pdf - dist.pdfUv(uv)) > 1e-6f * pdf) ++inconsistent;
        const int x = int(uv.x * float(w) * 2.0f), y = int(uv.y * float(h) * 2.0f);
        observed[size_t(((y / 2) * w + x / 2) * 4 + (y % 2) * 2 + x % 2)] += 1.0;
    }
    EXPECT_EQ(inconsistent, 0);
    const auto chi = test::chiSquareTest(observed, expected);
    EXPECT_FALSE(chi.sampleInZeroCell) << "a black texel was sampled";
    EXPECT_GT(chi.pValue, 0.01) << "chi2 " << chi.statistic << " dof " << chi.dof;
}

TEST(EnvironmentDistribution, WeightsAreRadianceTimesSinTheta) {
    const Image map = testMap();
    const EnvironmentDistribution dist(map);
    // pdf(u, v) ∝ max(rgb) sinθ: compare two texels of the same value in different rows.
    const float a = dist.pdfUv(glm::vec2(0.5f / 24.0f, 0.5f / 12.0f));   // x 0, y 0: value 0.2
    const float b = dist.pdfUv(glm::vec2(5.5f / 24.0f, 0.5f / 12.0f));   // black column
    EXPECT_EQ(b, 0.0f);
    EXPECT_NEAR(a / dist.pdfUv(glm::vec2(0.5f / 24.0f, 5.5f / 12.0f)) *
                    (0.2f + 0.1f * float((0 * 7 + 5 * 3) % 5)) / 0.2f,
                std::sin(0.5 / 12.0 * M_PI) / std::sin(5.5 / 12.0 * M_PI), 1e-5);
    // A black map samples nothing.
    Image black(8, 4);
    EXPECT_EQ(EnvironmentDistribution(black).meanWeight(), 0.0f);
}
