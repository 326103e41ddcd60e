// The ambient-occlusion view (debug_views.glsl debugAmbientOcclusion): 1 where nothing lies within
// ao.distance of the first hit, about 1/2 at the foot of a wall (half the cosine-weighted
// hemisphere faces the wall), (h/d)² between two parallel planes h apart, and ao.rays = k rays
// per sample leave the mean and divide one sample's variance by k.
#include "scene/scene_loader.h"
#include "support/debug_view_render.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace raylab {
namespace {

// Every check below holds within z standard errors: two-sided α = 4.7e-4 each, 0.001 for each
// test's family of two (Šidák).
constexpr double kZ = 3.5;

class AmbientOcclusionTest : public test::GlTest {
protected:
    // A floor (y = 0) seen from 2 units straight above, filling the view; with `wall` it ends at
    // z = -0.5 in a wall 5 units high.
    static Scene scene(bool wall) {
        const std::string back = wall ? "-0.5" : "-5";
        std::string objects = R"({ "type": "mesh", "positions": [-5, 0, )" + back + ",  5, 0, " + back +
                              R"(,  5, 0, 5,  -5, 0, 5], "indices": [0, 1, 2,  0, 2, 3] })";
        if (wall)
            objects +=
                R"(, { "type": "mesh", "positions": [-5, 0, -0.5,  5, 0, -0.5,  5, 5, -0.5,  -5, 5, -0.5], "indices": [0, 1, 2,  0, 2, 3] })";
        return parseScene(R"({ "camera": { "position": [0, 2, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 60 },
                               "render": { "width": 24, "height": 32, "spp": 64, "rpp": 16 },
                               "objects": [)" + objects + "] }",
                          "ao.json");
    }

    // Two planes 100 units wide, y = 0 and y = 1 (h = 1), the camera between them looking down at
    // a patch of the lower one so small that every pixel sees the same (h/d)².
    static Scene planes(double distance, int rays, int spp, int size, int seed = 7,
                        const std::string& sampler = "independent") {
        const std::string quad = R"(, "indices": [0, 1, 2,  0, 2, 3] })";
        return parseScene(R"({ "camera": { "position": [0, 0.5, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 10 },
                               "render": { "width": )" + std::to_string(size) + R"(, "height": )" + std::to_string(size) +
                              R"(, "spp": )" + std::to_string(spp) + R"(, "rpp": 16, "sampler": ")" + sampler + R"(", "seed": )" + std::to_string(seed) + R"( },
                               "ao": { "distance": )" + std::to_string(distance) + R"(, "rays": )" + std::to_string(rays) + R"( },
                               "objects": [
                                 { "type": "mesh", "positions": [-50, 0, -50,  50, 0, -50,  50, 0, 50,  -50, 0, 50])" + quad + R"(,
                                 { "type": "mesh", "positions": [-50, 1, -50,  50, 1, -50,  50, 1, 50,  -50, 1, 50])" + quad + R"( ] })",
                          "planes.json");
    }

    static Image ambientOcclusion(const Scene& s) { return test::renderView(s, DebugView::Ao); }

    static double rowMean(const Image& im, int y) {
        double sum = 0.0;
        for (int x = 0; x < im.width; ++x) sum += im.rgb(x, y).x;
        return sum / im.width;
    }

    // Mean and (unbiased) variance of the red channel over all pixels.
    static std::pair<double, double> moments(const Image& im) {
        double sum = 0.0, sumSq = 0.0;
        const double n = double(im.width) * im.height;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) {
                const double v = im.rgb(x, y).x;
                sum += v;
                sumSq += v * v;
            }
        const double mean = sum / n;
        return {mean, (sumSq - n * mean * mean) / (n - 1.0)};
    }
};

TEST_F(AmbientOcclusionTest, APlaneUnderAnOpenSkyIsUnoccluded) {
    const Image im = ambientOcclusion(scene(false));
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) ASSERT_EQ(im.rgb(x, y).x, 1.0f) << x << ", " << y;
}

TEST_F(AmbientOcclusionTest, TheFootOfAWallIsHalfOccluded) {
    const Image im = ambientOcclusion(scene(true));
    // The bottom row sees the floor more than 1 unit (ao.distance) from the wall, the top row the
    // wall more than 1 unit above the floor: nothing occludes either.
    EXPECT_EQ(rowMean(im, im.height - 1), 1.0);
    EXPECT_EQ(rowMean(im, 0), 1.0);
    double least = 1.0;
    for (int y = 0; y < im.height; ++y) {
        least = std::min(least, rowMean(im, y));
        for (int x = 0; x < im.width; ++x) {
            ASSERT_GE(im.rgb(x, y).x, 0.0f);
            ASSERT_LE(im.rgb(x, y).x, 1.0f);
        }
    }
    EXPECT_NEAR(least, 0.5, 0.1) << "the row at the corner";
}

// A cosine-weighted direction has cos²θ uniform in [0, 1]; it meets the plane at height h within d
// exactly when cosθ > h/d, so the open fraction is (h/d)². Each of the 16 × 16 pixels × 16 samples ×
// 4 rays is one Bernoulli trial of that probability (independent sampler, fixed seed).
TEST_F(AmbientOcclusionTest, BetweenParallelPlanesTheOpenFractionIsHOverDSquared) {
    Scene s = planes(1.25, 4, 16, 16);
    PathTracer tracer(variantOptions(TracerVariant::Views, TracerEntry::Fragment));
    tracer.setScene(s);
    const unsigned program = tracer.program().id();
    for (double d : {1.25, 2.0}) {
        SCOPED_TRACE("ao.distance " + std::to_string(d));
        s.ao.distance = float(d);
        tracer.updateSettings(s);   // what the viewer does for a reset-accumulation key
        EXPECT_EQ(tracer.program().id(), program) << "ao.distance is a uniform: no other program";
        setTracedView(tracer.program(), DebugView::Ao, 0);
        renderProgressively(tracer, s.render);
        const double p = 1.0 / (d * d);
        const double trials = 16.0 * 16.0 * 16.0 * 4.0;
        EXPECT_NEAR(moments(tracer.readImage()).first, p, kZ * std::sqrt(p * (1.0 - p) / trials));
    }
}

// With k rays a sample is B/k, B binomial(k, p): its variance p(1 - p)/k, and the variance of
// the sample variance over n pixels (μ4 − σ⁴)/n with μ4 = 3(pq)²/k² + pq(1 − 6pq)/k³. One sample
// per pixel, d = 2 (p = 1/4), 64 × 64 pixels with the same expectation.
TEST_F(AmbientOcclusionTest, KRaysPerSampleKeepTheMeanAndDivideTheVarianceByK) {
    const double p = 0.25, pq = p * (1.0 - p), n = 64.0 * 64.0;
    double variance[2] = {};
    const int ks[2] = {1, 8};
    for (int i = 0; i < 2; ++i) {
        const double k = ks[i];
        SCOPED_TRACE("ao.rays " + std::to_string(ks[i]));
        const auto [mean, var] = moments(ambientOcclusion(planes(2.0, ks[i], 1, 64, 1)));
        EXPECT_NEAR(mean, p, kZ * std::sqrt(pq / k / n));
        const double sigma2 = pq / k;
        const double mu4 = 3.0 * pq * pq / (k * k) + pq * (1.0 - 6.0 * pq) / (k * k * k);
        EXPECT_NEAR(var, sigma2, kZ * std::sqrt((mu4 - sigma2 * sigma2) / n));
        variance[i] = var;
    }
    EXPECT_GT(variance[0] / variance[1], 6.0) << "about 8 times less";
}

// The AO rays take the render's sampler (bounce 0's BSDF dimensions, sample s·k + i for ray i), so
// a pixel's 16 rays (16 samples of 1 ray, or 4 of 4) are stratified as its bounces are. Between
// the planes (h/d = 1/2) a ray is open where the concentric map's max(|2u − 1|) > √3/2: a frame of
// width w = (1 − √3/2)/2 around the unit square. Independent rays give a pixel binomial variance
// pq/16; jittered 4 × 4 strata give Σ p_k q_k / 16², p_k the open share of stratum k, as only the
// 12 strata the frame crosses vary; the Sobol samplers fall well below both. 64 × 64 pixels; the
// family of ten 3.5σ checks: α ≈ 0.005 (the bounds of 1/2 are far outside any noise).
TEST_F(AmbientOcclusionTest, StratifyingSamplersSpreadAPixelsRaysAndScatterLess) {
    const double p = 0.25, n = 64.0 * 64.0;
    // Mean and variance of the sample variance of a pixel's mean of 16 independent Bernoulli(p_k).
    const auto expectVariance = [&](const double(&pk)[16], double var, const std::string& what) {
        double sum2 = 0.0, sum4 = 0.0, mu4 = 0.0;
        for (double pp : pk) {
            const double s2 = pp * (1.0 - pp);
            sum2 += s2;
            sum4 += s2 * s2;
            mu4 += s2 * (1.0 - 3.0 * s2);
        }
        const double sigma2 = sum2 / 256.0;
        const double mu4Mean = (mu4 + 3.0 * (sum2 * sum2 - sum4)) / (256.0 * 256.0);
        EXPECT_NEAR(var, sigma2, kZ * std::sqrt((mu4Mean - sigma2 * sigma2) / n)) << what;
    };
    double binomial[16], strata[16];
    const double w = (1.0 - std::sqrt(3.0) / 2.0) / 2.0;
    const auto inner = [&](int i) {   // length of stratum column i inside [w, 1 − w]
        return std::max(0.0, std::min((i + 1) / 4.0, 1.0 - w) - std::max(i / 4.0, w));
    };
    for (int k = 0; k < 16; ++k) {
        binomial[k] = p;
        strata[k] = 1.0 - inner(k % 4) * inner(k / 4) * 16.0;
    }
    const auto [mean, independent] = moments(ambientOcclusion(planes(2.0, 1, 16, 64, 1)));
    EXPECT_NEAR(mean, p, kZ * std::sqrt(p * (1.0 - p) / 16.0 / n));
    expectVariance(binomial, independent, "independent: binomial");
    for (const char* sampler : {"stratified", "sobol", "zsobol"}) {
        SCOPED_TRACE(sampler);
        for (int rays : {1, 4}) {
            SCOPED_TRACE("ao.rays " + std::to_string(rays));
            const auto [m, var] = moments(ambientOcclusion(planes(2.0, rays, 16 / rays, 64, 1, sampler)));
            EXPECT_NEAR(m, p, kZ * std::sqrt(p * (1.0 - p) / 16.0 / n));
            if (std::string(sampler) == "stratified")
                expectVariance(strata, var, "jittered 4 x 4");   // 3.5σ bands of the two: disjoint
            else
                EXPECT_LT(var, 0.5 * independent);
        }
    }
}

} // namespace
} // namespace raylab
