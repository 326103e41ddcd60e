// Light sampling (shaders/include/light_sampling.glsl) on the CPU: the sphere cone and the
// uniform sphere against their pdfs, and the power heuristic.
#include "shaders/include/light_sampling.glsl"
#include "shaders/include/random.glsl"
#include "support/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace raylab;
using namespace raylab::glsl;

TEST(ShaderLightSampling, SphereConeSamplesAreUniformInTheSubtendedCone) {
    // χ² over cells (1 − cosθ, φ) around the axis to the centre, cosθ ∈ [cosθmax, 1]: the cone's
    // pdf is constant, so each of the equal-(1 − cos) cells expects N × pdf × its solid angle.
    // Distances from just outside the sphere to 10^4 radii (the small-cone Taylor branch).
    // 6 tests, Šidák-corrected α = 0.01, 10^6 samples each. Samples outside the cone fail outright.
    const float distances[] = {1.05f, 1.5f, 3.0f, 20.0f, 300.0f, 1e4f};
    const double perTest = test::sidak(0.01, 6);
    const vec3 center(0.3f, -0.2f, 0.5f);
    const float radius = 0.7f;
    uint seed = 1;
    for (float d : distances) {
        SCOPED_TRACE("distance / radius " + std::to_string(d));
        const vec3 axis = glm::normalize(vec3(0.2f, 1.0f, -0.4f));
        const vec3 p = center - axis * (d * radius);
        const double oneMinusCosMax = double(sphereConeOneMinusCos(p, center, radius));
        const double exactOneMinusCos = 1.0 - std::sqrt(1.0 - 1.0 / (double(d) * d));
        ASSERT_NEAR(oneMinusCosMax, exactOneMinusCos, 1e-3 * exactOneMinusCos);
        const float pdf = sphereConePdf(p, center, radius);
        const Frame f = frameFromNormal(axis);
        constexpr int nt = 20, nphi = 40, n = 1000000;
        std::vector<double> observed(nt * nphi, 0.0), expected(nt * nphi, 0.0);
        for (int i = 0; i < nt * nphi; ++i)   // ∫cell pdf dω = pdf × (Δ(1 − cos)) × Δφ
            expected[size_t(i)] = n * double(pdf) * (oneMinusCosMax / nt) * (2 * M_PI / nphi);
        Rng rng = rngCreate(uvec2(++seed, 0), 0u, 3u);
        int outside = 0;
        for (int k = 0; k < n; ++k) {
            const vec3 w = sphereConeSample(p, center, radius, rngNext2(rng));
            ASSERT_NEAR(glm::length(w), 1.0f, 1e-5f);
            const vec3 l = frameToLocal(f, w);
            const double omc = 1.0 - double(l.z);
            // In the cone: the ray from p along w meets the sphere (float tolerance at the rim).
            if (omc > oneMinusCosMax * (1.0 + 1e-3) + 1e-7) ++outside;
            double phi = std::atan2(double(l.y), double(l.x));
            if (phi < 0) phi += 2 * M_PI;
            const int it = std::clamp(int(omc / oneMinusCosMax * nt), 0, nt - 1);
            const int ip = std::min(int(phi / (2 * M_PI) * nphi), nphi - 1);
            observed[size_t(it * nphi + ip)] += 1.0;
        }
        EXPECT_EQ(outside, 0);
        if (d >= 300.0f) continue;   // float cosθ cannot resolve cells of a cone this narrow
        const auto chi = test::chiSquareTest(observed, expected);
        EXPECT_GT(chi.pValue, perTest) << "chi2 " << chi.statistic << " dof " << chi.dof;
    }
}

TEST(ShaderLightSampling, NarrowConesAreUniformInTheirTangentPlane) {
    // For cones too narrow for cosθ bins, test in the tangent plane: (sinθ/sinθmax)² is uniform.
    const vec3 center(0.0f);
    const float radius = 1.0f;
    for (float d : {300.0f, 1e4f}) {
        const vec3 p(0.0f, 0.0f, -d);
        const Frame f = frameFromNormal(vec3(0, 0, 1));
        constexpr int nt = 20, nphi = 40, n = 1000000;
        std::vector<double> observed(nt * nphi, 0.0), expected(nt * nphi, double(n) / (nt * nphi));
        Rng rng = rngCreate(uvec2(9, 0), 0u, 4u);
        const double sin2Max = 1.0 / (double(d) * d);
        for (int k = 0; k < n; ++k) {
            const vec3 l = frameToLocal(f, sphereConeSample(p, center, radius, rngNext2(rng)));
            const double s2 = double(l.x) * l.x + double(l.y) * l.y;
            double phi = std::atan2(double(l.y), double(l.x));
            if (phi < 0) phi += 2 * M_PI;
            const int it = std::clamp(int(s2 / sin2Max * nt), 0, nt - 1);
            observed[size_t(it * nphi + std::min(int(phi / (2 * M_PI) * nphi), nphi - 1))] += 1.0;
        }
        EXPECT_GT(test::chiSquareTest(observed, expected).pValue, test::sidak(0.01, 2)) << d;
    }
}

TEST(ShaderLightSampling, InsideOrOnTheSphereThereIsNoCone) {
    EXPECT_EQ(sphereConePdf(vec3(0.0f), vec3(0.0f), 1.0f), 0.0f);
    EXPECT_EQ(sphereConePdf(vec3(1.0f, 0.0f, 0.0f), vec3(0.0f), 1.0f), 0.0f);
    EXPECT_GT(sphereConePdf(vec3(1.1f, 0.0f, 0.0f), vec3(0.0f), 1.0f), 0.0f);
}

TEST(ShaderLightSampling, UniformSphereMatchesItsPdf) {
    constexpr int nz = 20, nphi = 40, n = 1000000;
    std::vector<double> observed(nz * nphi, 0.0), expected(nz * nphi, double(n) / (nz * nphi));
    Rng rng = rngCreate(uvec2(1, 0), 0u, 8u);
    for (int k = 0; k < n; ++k) {
        const vec3 w = sampleUniformSphere(rngNext2(rng));
        double phi = std::atan2(double(w.y), double(w.x));
        if (phi < 0) phi += 2 * M_PI;
        const int iz = std::clamp(int((w.z + 1.0f) / 2.0f * nz), 0, nz - 1);
        observed[size_t(iz * nphi + std::min(int(phi / (2 * M_PI) * nphi), nphi - 1))] += 1.0;
    }
    EXPECT_GT(test::chiSquareTest(observed, expected).pValue, 0.01);
    EXPECT_NEAR(double(UNIFORM_SPHERE_PDF), 1.0 / (4.0 * M_PI), 1e-8);   // float: one ulp is 7e-9
}

TEST(ShaderLightSampling, PowerHeuristicWeightsSumToOne) {
    for (float a : {1e-30f, 0.1f, 1.0f, 7.0f, 1e30f})
        for (float b : {1e-30f, 0.2f, 1.0f, 3.0f, 1e30f}) {
            const float s = powerHeuristic(a, b) + powerHeuristic(b, a);
            ASSERT_TRUE(std::isfinite(s));
            EXPECT_NEAR(s, 1.0f, 1e-5f) << a << " " << b;
        }
    EXPECT_EQ(powerHeuristic(0.0f, 1.0f), 0.0f);
    EXPECT_EQ(powerHeuristic(1.0f, 0.0f), 1.0f);
    EXPECT_NEAR(powerHeuristic(1.0f, 2.0f), 0.2f, 1e-6f);
}
