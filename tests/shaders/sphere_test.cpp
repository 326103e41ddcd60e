// Ray–sphere intersection (the shader's code on the CPU) against a double-precision reference.
#include "shaders/include/frame.glsl"
#include "shaders/include/random.glsl"
#include "shaders/include/sampling.glsl"
#include "shaders/include/sphere.glsl"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab::glsl;

namespace {

// Reference: distance from the centre to the line, in double.
bool referenceHits(glm::dvec3 o, glm::dvec3 d, glm::dvec3 c, double r) {
    d = glm::normalize(d);
    const glm::dvec3 f = o - c;
    const glm::dvec3 perp = f - glm::dot(f, d) * d;
    return glm::dot(f, d) < 0.0 && glm::dot(perp, perp) < r * r;
}

} // namespace

TEST(ShaderSphere, HitsAndMissesAgreeWithDoubleForTinyFarSpheres) {
    // Rays aimed at random points of a disk 1.2 radii wide around a sphere 1 unit away, for
    // radius / distance from 1e-1 to 1e-5. Ray Tracing Gems ch. 7 measured the textbook formula
    // wrong on 47% of these decisions at 1e-4; the improved form should be near zero.
    Rng rng = rngCreate(uvec2(1, 1), 0u, 5u);
    for (double ratio : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5}) {
        int disagreements = 0, decided = 0;
        const float r = float(ratio);
        for (int i = 0; i < 20000; ++i) {
            const vec2 u = rngNext2(rng);
            const vec3 target(r * 1.2f * (2 * u.x - 1), r * 1.2f * (2 * u.y - 1), 0.0f);
            const vec3 origin(0.0f, 0.0f, 1.0f);
            const vec3 dir = target - origin;
            // Skip rays within float rounding of the silhouette: neither answer is wrong there.
            const glm::dvec3 dd = glm::normalize(glm::dvec3(dir));
            const glm::dvec3 f = glm::dvec3(origin);
            const double dist = glm::length(f - glm::dot(f, dd) * dd);
            if (std::abs(dist - ratio) < ratio * 1e-4) continue;
            ++decided;
            const bool hit = intersectSphere(Ray(origin, dir), vec3(0.0f), r, 0.0f, FLOAT_MAX) > 0.0f;
            if (hit != referenceHits(glm::dvec3(origin), glm::dvec3(dir), glm::dvec3(0.0), ratio)) ++disagreements;
        }
        EXPECT_LE(double(disagreements) / decided, 1e-4) << "r/d = " << ratio;
    }
}

TEST(ShaderSphere, NearestRootFromOutsideAndInside) {
    const vec3 c(0.0f, 0.0f, -5.0f);
    EXPECT_NEAR(intersectSphere(Ray(vec3(0.0f), vec3(0, 0, -1)), c, 1.0f, 0.0f, FLOAT_MAX), 4.0f, 1e-5f);
    // From inside, the far root.
    EXPECT_NEAR(intersectSphere(Ray(c, vec3(0, 0, -1)), c, 1.0f, 0.0f, FLOAT_MAX), 1.0f, 1e-5f);
    // Behind the ray, and beyond tMax: misses.
    EXPECT_LT(intersectSphere(Ray(vec3(0.0f), vec3(0, 0, 1)), c, 1.0f, 0.0f, FLOAT_MAX), 0.0f);
    EXPECT_LT(intersectSphere(Ray(vec3(0.0f), vec3(0, 0, -1)), c, 1.0f, 0.0f, 3.0f), 0.0f);
    // Unnormalised directions give t in units of the direction's length.
    EXPECT_NEAR(intersectSphere(Ray(vec3(0.0f), vec3(0, 0, -2)), c, 1.0f, 0.0f, FLOAT_MAX), 2.0f, 1e-5f);
}

TEST(ShaderSphere, RaysLeavingTheSurfaceDoNotHitItAgain) {
    // Re-intersection: spheres with centres and radii drawn log-uniformly over 10^±3 (so a radius
    // can be far smaller or far larger than the centre's coordinates, like a ground sphere of
    // radius 1000 at y = -1000), rays leaving each surface in cosine-distributed directions, down
    // to grazing: an outgoing ray must miss its own sphere, an ingoing one must reach the far side.
    Rng rng = rngCreate(uvec2(9, 9), 0u, 1u);
    auto logUniform = [&](float lo, float hi) {
        return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * rngNextFloat(rng));
    };
    int selfHits = 0, lostInside = 0, rays = 0;
    for (int shape = 0; shape < 300; ++shape) {
        const vec3 dirC = glm::normalize(vec3(rngNextFloat(rng) - 0.5f, rngNextFloat(rng) - 0.5f, rngNextFloat(rng) - 0.5f));
        const vec3 c = dirC * logUniform(1e-3f, 1e3f);
        const float radius = logUniform(1e-3f, 1e3f);
        for (int i = 0; i < 200; ++i) {
            const vec2 u = rngNext2(rng);
            const float z = 1 - 2 * u.x, s = std::sqrt(std::max(0.0f, 1 - z * z));
            const vec3 n(s * std::cos(2 * PI * u.y), s * std::sin(2 * PI * u.y), z);
            const vec3 p = sphereSurfacePoint(c + radius * n, c, radius);
            const vec3 err = sphereHitError(c, radius);
            vec3 local = sampleCosineHemisphere(rngNext2(rng));
            if (i % 4 == 0) local = glm::normalize(vec3(local.x, local.y, 1e-3f));   // grazing
            const bool inward = i % 2 == 1;
            const vec3 side = inward ? -n : n;
            const vec3 dir = frameToWorld(frameFromNormal(side), local);
            const Ray ray(offsetRayOrigin(p, side, err), dir);
            const float t = intersectSphere(ray, c, radius, 0.0f, FLOAT_MAX);
            ++rays;
            if (!inward) {
                selfHits += t > 0.0f;
            } else {
                // The chord to the far side has length 2r·cosθ; a hit much nearer is a self-hit.
                const float chord = 2.0f * radius * local.z;
                if (t <= 0.0f) ++lostInside;
                else if (t < 0.5f * chord) ++selfHits;
            }
        }
    }
    EXPECT_EQ(selfHits, 0) << "of " << rays << " rays";
    EXPECT_EQ(lostInside, 0) << "of " << rays << " rays";
}
