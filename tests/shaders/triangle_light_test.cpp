// Triangle lights on the CPU (shaders/include/triangle_light.glsl): the solid angle a triangle
// subtends, Arvo's uniform map onto it (χ² over sub-triangles whose solid angles are computed in
// double), and sampleTriangleLight's choice between solid angle and area with the pdf that MIS
// weighs a BSDF sample by.
#include "shaders/include/random.glsl"
#include "shaders/include/triangle_light.glsl"
#include "support/statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace raylab;
using namespace raylab::glsl;

namespace {

// The solid angle of triangle (a, b, c) seen from the origin, in double (Van Oosterom & Strackee).
double solidAngle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    a = glm::normalize(a), b = glm::normalize(b), c = glm::normalize(c);
    return std::abs(2.0 * std::atan2(std::abs(glm::dot(a, glm::cross(b, c))),
                                     1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a)));
}

// Where the ray from the origin along w meets the plane of (a, b, c), as barycentrics (u, v) of b
// and c, in double; t <= 0 when it meets the plane behind the origin.
struct PlaneHit { double u, v, t; };
PlaneHit planeHit(glm::dvec3 w, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, pv = glm::cross(w, e2);
    const double det = glm::dot(e1, pv);
    const glm::dvec3 tv = -a, qv = glm::cross(tv, e1);
    return {glm::dot(tv, pv) / det, glm::dot(w, qv) / det, glm::dot(e2, qv) / det};
}

// The triangle split into n² sub-triangles of a regular grid in (u, v): cell of a point, and the
// corners of each cell.
int cellOf(double u, double v, int n) {
    const int i = std::clamp(int(u * n), 0, n - 1), j = std::clamp(int(v * n), 0, n - 1 - i);
    const bool upper = u * n - i + (v * n - j) > 1.0 && i + j < n - 1;
    return (i * n + j) * 2 + (upper ? 1 : 0);
}

struct Case { const char* name; vec3 a, b, c; };

// Seen from the origin: Ω from 10⁻³ sr (SPHERICAL_TRIANGLE_MIN_SOLID_ANGLE) to about 6.2 sr, slivers,
// and one seen edge-on enough that area sampling's pdf varies by orders of magnitude over it.
const Case kCases[] = {
    {"small and far", {-0.3f, 5.0f, -0.2f}, {0.3f, 5.0f, -0.2f}, {0.0f, 5.1f, 0.4f}},
    {"the Cornell lamp from the wall's top", {343, 48.7f, 227}, {343, 48.7f, 332}, {213, 48.7f, 332}},
    {"close and large", {-2.0f, 0.5f, -1.5f}, {2.5f, 0.5f, -1.0f}, {0.0f, 0.6f, 2.5f}},
    {"nearly a hemisphere", {-30.0f, 0.4f, -20.0f}, {30.0f, 0.4f, -20.0f}, {0.0f, 0.4f, 40.0f}},
    {"grazing", {-1.0f, 0.2f, 2.0f}, {1.0f, 0.2f, 2.0f}, {0.0f, 0.3f, 5.0f}},
    {"sliver", {-1.0f, 1.0f, 1.0f}, {1.0f, 1.0f, 1.0f}, {0.0f, 1.0f, 1.02f}},
    // A thin one at 2·10⁻³ sr with each vertex first: with its obtuse vertex as b, 1 − z² lost the
    // samples at u.y → 1 past the far edge before the slerp.
    {"thin, obtuse vertex c", {-0.2f, 1.0f, 1.0f}, {0.2f, 1.0f, 1.0f}, {0.0f, 1.0f, 1.03f}},
    {"thin, obtuse vertex b", {0.2f, 1.0f, 1.0f}, {0.0f, 1.0f, 1.03f}, {-0.2f, 1.0f, 1.0f}},
    {"thin, obtuse vertex a", {0.0f, 1.0f, 1.03f}, {-0.2f, 1.0f, 1.0f}, {0.2f, 1.0f, 1.0f}},
    {"thin at the lower bound", {0.0f, 1.0f, 1.05f}, {-0.06f, 1.0f, 1.0f}, {0.06f, 1.0f, 1.0f}},
};

} // namespace

TEST(ShaderTriangleLight, TheSolidAngleIsTheDoublePrecisionOne) {
    // And the octant, π/2.
    EXPECT_NEAR(triangleSolidAngle(vec3(0.0f), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)), M_PI / 2, 1e-6);
    for (const Case& k : kCases) {
        SCOPED_TRACE(k.name);
        const double exact = solidAngle(k.a, k.b, k.c);
        EXPECT_NEAR(triangleSolidAngle(vec3(0.0f), k.a, k.b, k.c), exact, 1e-5 * exact);
    }
    EXPECT_EQ(triangleSolidAngle(vec3(1, 2, 3), vec3(1, 2, 3), vec3(0, 1, 0), vec3(0, 0, 1)), 0.0f)
        << "a vertex at the point";
}

TEST(ShaderTriangleLight, ArvoSamplesAreUniformOverTheSphericalTriangle) {
    // Each sample's direction is followed in double to the triangle's plane: it must meet the
    // triangle (within 10⁻⁴ of an edge in barycentrics), and over the 2·16² cells of a regular
    // split of the triangle its counts must follow each cell's own solid angle. 10⁶ samples a case
    // from the map alone (sampleSphericalTriangle); one test a case, Šidák-corrected α = 0.01.
    const double perTest = test::sidak(0.01, int(std::size(kCases)));
    constexpr int n = 16, samples = 1000000;
    uint seed = 40;
    for (const Case& k : kCases) {
        SCOPED_TRACE(k.name);
        const glm::dvec3 a(k.a), b(k.b), c(k.c);
        const double total = solidAngle(a, b, c);
        std::vector<double> expected(size_t(2 * n * n), 0.0), observed(expected.size(), 0.0);
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j) {
                const glm::dvec3 du = (b - a) / double(n), dv = (c - a) / double(n);
                const glm::dvec3 o = a + double(i) * du + double(j) * dv;
                const size_t cell = size_t((i * n + j) * 2);
                expected[cell] = samples * solidAngle(o, o + du, o + dv) / total;
                if (i + j < n - 1) expected[cell + 1] = samples * solidAngle(o + du, o + du + dv, o + dv) / total;
            }
        const float area = triangleSolidAngle(vec3(0.0f), k.a, k.b, k.c);
        Rng rng = rngCreate(uvec2(++seed, 0), 0u, 7u);
        int off = 0;
        for (int s = 0; s < samples; ++s) {
            const vec3 w = sampleSphericalTriangle(glm::normalize(k.a), glm::normalize(k.b), glm::normalize(k.c),
                                                   k.b - k.a, k.c - k.a, area, rngNext2(rng));
            ASSERT_NEAR(glm::length(w), 1.0f, 1e-5f);
            const PlaneHit h = planeHit(glm::dvec3(w), a, b, c);
            if (!(h.t > 0.0 && h.u > -1e-4 && h.v > -1e-4 && h.u + h.v < 1.0 + 1e-4)) ++off;
            observed[size_t(cellOf(h.u, h.v, n))] += 1.0;
        }
        EXPECT_EQ(off, 0) << "directions that miss the triangle";
        std::vector<double> obs, exp;   // the grid's unused upper cells of its last diagonal hold nothing
        for (size_t i = 0; i < expected.size(); ++i)
            if (expected[i] > 0.0) obs.push_back(observed[i]), exp.push_back(expected[i]);
        const auto chi = test::chiSquareTest(obs, exp);
        EXPECT_FALSE(chi.sampleInZeroCell);
        EXPECT_GT(chi.pValue, perTest) << "chi2 " << chi.statistic << " dof " << chi.dof;
    }
}

TEST(ShaderTriangleLight, ALightIsSampledBySolidAngleWhereThatIsWellConditioned) {
    // Small far triangles, and those filling nearly a hemisphere, take area sampling; the rest
    // solid angle. Either way the pdf sampleTriangleLight returns is the one
    // triangleLightDirectionPdf gives a BSDF sample meeting the same point (what MIS weighs with),
    // and the point lies on the light where the direction meets it.
    struct Expect { vec3 a, b, c; bool bySolidAngle; };
    const Expect cases[] = {
        {{-0.01f, 5.0f, 0.0f}, {0.01f, 5.0f, 0.0f}, {0.0f, 5.0f, 0.02f}, false},   // Ω ≈ 8·10⁻⁶
        {kCases[0].a, kCases[0].b, kCases[0].c, true},
        {kCases[1].a, kCases[1].b, kCases[1].c, true},
        {kCases[2].a, kCases[2].b, kCases[2].c, true},
        {{-300.0f, 0.4f, -200.0f}, {300.0f, 0.4f, -200.0f}, {0.0f, 0.4f, 400.0f}, false},   // Ω > 6.22
    };
    uint seed = 90;
    for (const Expect& k : cases) {
        const float omega = triangleSolidAngle(vec3(0.0f), k.a, k.b, k.c);
        SCOPED_TRACE("solid angle " + std::to_string(omega));
        EXPECT_EQ(triangleLightBySolidAngle(omega), k.bySolidAngle);
        const vec3 nrm = glm::normalize(glm::cross(k.b - k.a, k.c - k.a));
        const float area = 0.5f * glm::length(glm::cross(k.b - k.a, k.c - k.a));
        Rng rng = rngCreate(uvec2(++seed, 0), 0u, 7u);
        for (int s = 0; s < 10000; ++s) {
            vec3 wi, point;
            const float pdf = sampleTriangleLight(vec3(0.0f), k.a, k.b, k.c, area, rngNext2(rng), wi, point);
            ASSERT_TRUE(std::isfinite(pdf) && pdf > 0.0f);
            if (k.bySolidAngle) ASSERT_FLOAT_EQ(pdf, 1.0f / omega);
            const float dist2 = glm::dot(point, point);
            const float hitPdf = triangleLightDirectionPdf(vec3(0.0f), k.a, k.b, k.c, area, dist2, glm::dot(nrm, wi));
            ASSERT_NEAR(hitPdf, pdf, 1e-3f * pdf);
            ASSERT_NEAR(glm::dot(point - k.a, nrm), 0.0f, 1e-4f * std::sqrt(dist2)) << "the point is on the plane";
            ASSERT_NEAR(glm::dot(glm::normalize(point), wi), 1.0f, 1e-5f) << "along the direction";
        }
    }
}
