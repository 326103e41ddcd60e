// Numerical stress tests of the shared intersection code (the shader's own maths on the CPU):
// re-intersection at extreme scales, watertightness of a closed mesh, huge coordinates,
// degenerate triangles, zero direction components, and a double-precision sphere reference.
#include "accel/cpu_traversal.h"
#include "scene/transform.h"
#include "shaders/include/aabb.glsl"
#include "shaders/include/frame.glsl"
#include "shaders/include/random.glsl"
#include "shaders/include/sampling.glsl"
#include "shaders/include/sphere.glsl"
#include "shaders/include/triangle.glsl"
#include "support/far_objects.h"
#include "support/stress_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace raylab::glsl;

namespace {

using Sampler = raylab::test::StressSampler;

bool finite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

TEST(IntersectionStress, ThousandShapesAtScales1eMinus4To1e4HaveNoSelfHits) {
    // 500 spheres and 500 triangles, positions and sizes log-uniform over 10^±4; 1000 rays leave
    // each surface from a point found by a real intersection, towards either side for triangles
    // and outwards for spheres (grazing ones included). Any hit of the same shape is a self-hit.
    Sampler s{rngCreate(uvec2(4, 4), 0u, 4u)};
    int selfHits = 0, rays = 0, setupMisses = 0, sphereSelfHits = 0, representableMisses = 0;
    for (int shape = 0; shape < 1000; ++shape) {
        const vec3 position = s.unitVector() * s.logUniform(1e-4f, 1e4f);
        const float size = s.logUniform(1e-4f, 1e4f);
        const bool sphere = shape % 2 == 0;
        // Shapes at least 1000 float spacings across at their position: every setup ray must hit.
        const bool representable = size > 1000.0f * 5.96e-8f * std::max(std::abs(position.x),
                                                                         std::max(std::abs(position.y), std::abs(position.z)));
        const vec3 p0 = position + size * s.unitVector();
        const vec3 p1 = position + size * s.unitVector();
        const vec3 p2 = position + size * s.unitVector();
        for (int i = 0; i < 1000; ++i) {
            // A ray from afar onto a random point of the shape.
            vec3 target;
            bool inner = true;   // aimed at least 64 float spacings away from the triangle's edges
            if (sphere) {
                target = position + size * s.unitVector();
            } else {
                vec2 b = s.next2();
                if (b.x + b.y > 1.0f) b = vec2(1.0f) - b;
                // Distance from the aimed-at point to the nearest edge: b_i × the height over it.
                const float twiceArea = length(cross(p1 - p0, p2 - p0));
                const float edgeDistance = std::min(std::min((1.0f - b.x - b.y) * twiceArea / length(p2 - p1),
                                                             b.x * twiceArea / length(p0 - p2)),
                                                    b.y * twiceArea / length(p1 - p0));
                inner = edgeDistance > 64.0f * 5.96e-8f * std::max(std::abs(position.x),
                                                                  std::max(std::abs(position.y), std::abs(position.z)));
                target = (1.0f - b.x - b.y) * p0 + b.x * p1 + b.y * p2;
            }
            // From the side the surface faces (never grazing: cosθ ≥ 0.1), 10 sizes away.
            vec3 facing = sphere ? normalize(target - position) : normalize(cross(p1 - p0, p2 - p0));
            if (!sphere && i % 2 == 1) facing = -facing;
            vec3 back = sampleCosineHemisphere(s.next2());
            back = normalize(vec3(back.x, back.y, std::max(back.z, 0.1f)));
            const vec3 from = target + 10.0f * size * frameToWorld(frameFromNormal(facing), back);
            const Ray in(from, target - from);
            vec3 p, n, err;
            if (sphere) {
                const float t = intersectSphere(in, position, size, 0.0f, FLOAT_MAX);
                if (t <= 0.0f) {
                    ++setupMisses;
                    representableMisses += representable;
                    continue;
                }
                p = sphereSurfacePoint(rayAt(in, t), position, size);
                n = normalize(p - position);
                err = sphereHitError(position, size);
            } else {
                TriangleHit h{};
                if (!intersectTriangle(in, p0, p1, p2, FLOAT_MAX, h)) {
                    ++setupMisses;
                    representableMisses += representable && inner;
                    continue;
                }
                p = triangleHitPoint(h, p0, p1, p2);
                err = triangleHitError(h, p0, p1, p2);
                n = dot(cross(p1 - p0, p2 - p0), in.dir) < 0.0f ? normalize(cross(p1 - p0, p2 - p0))
                                                                : -normalize(cross(p1 - p0, p2 - p0));
            }
            vec3 local = sampleCosineHemisphere(s.next2());
            if (i % 4 == 0) local = normalize(vec3(local.x, local.y, 1e-3f));   // grazing
            const Ray out(offsetRayOrigin(p, n, err), frameToWorld(frameFromNormal(n), local));
            ++rays;
            if (sphere) {
                const bool bad = intersectSphere(out, position, size, 0.0f, FLOAT_MAX) > 0.0f;
                selfHits += bad;
                sphereSelfHits += bad;
            } else {
                TriangleHit again{};
                selfHits += intersectTriangle(out, p0, p1, p2, FLOAT_MAX, again);
            }
        }
    }
    EXPECT_EQ(selfHits, 0) << "of " << rays << " rays; spheres: " << sphereSelfHits;
    // A setup ray can miss where a shape is smaller than the float spacing at its position
    // (size 1e-4 at 1e4, where floats are 1e-3 apart): its vertices, or the aimed-at point,
    // round off the surface, and float-degenerate triangles are never hit. Reported, and
    // bounded so that a broken intersector cannot pass unnoticed.
    RecordProperty("setup_misses", setupMisses);
    std::printf("re-intersection: %d rays, %d self-hits, %d setup rays missed\n", rays, selfHits, setupMisses);
    EXPECT_EQ(representableMisses, 0) << "missing geometry";
}

namespace {

// A bound on the distance between the float hit point (intersectSphere, then sphereSurfacePoint)
// and the double-precision one, for a ray from o (float inputs, the same for both), derived from
// float rounding in the manner of pbrt-v4 §6.8 (γ(n): n chained roundings):
//  - the foot of the perpendicular l = f + (b'/a)·d is computed from quantities of size |f|,
//    f = o − c, in about 10 roundings: the float line is the exact line displaced by at most
//    δ = γ(10)·|f| (the float direction itself is shared, so it adds nothing). Two lines δ apart
//    meet the sphere at points at most δ + |Δh| apart, h = √(r² − ρ²) the half-chord, and
//    |Δh| = |ρ1² − ρ2²| / (h1 + h2) ≤ min(2δ/cosθ, √(2rδ)) (θ the incidence angle: the error
//    grows towards the silhouette, where it is capped by the square root);
//  - t = c/q or q/a, each a handful of roundings from the same quantities: the point moves along
//    the ray by at most γ(10)·|f|, which re-projection onto the sphere enlarges by at most
//    r / (r − γ(10)·|f|);
//  - the re-projection and adding the centre back: sphereHitError (pbrt-v4 Sphere).
double sphereHitPointBound(glm::dvec3 o, glm::dvec3 c, double r, double cosTheta) {
    const double delta = double(gammaBound(10.0f)) * glm::length(o - c);
    const double chord = std::min(2.0 * delta / std::max(cosTheta, 1e-300), std::sqrt(2.0 * r * delta));
    const double along = delta * r / (r - delta);
    return delta + chord + along + double(glm::length(sphereHitError(vec3(c), float(r))));
}

} // namespace

TEST(IntersectionStress, SphereHitPointsAgreeWithDoubleWithinTheirErrorBound) {
    // Radius / distance from 1e-1 to 1e-5 and grazing rays within ±1e-4·r of the silhouette: the
    // float hit point (re-projected) lies within sphereHitError of the sphere, and within
    // sphereHitPointBound (above, from float rounding) of the double-precision hit point;
    // hit/miss agrees except within float rounding of the silhouette. The textbook quadratic
    // (b² − ac, which cancels catastrophically for small far spheres) must break the bound: it
    // is tight enough to tell a precise intersector from a naive one.
    Sampler s{rngCreate(uvec2(6, 2), 0u, 8u)};
    double worstRelativeError = 0.0, worstOfBound = 0.0;
    int textbookOutOfBound = 0, textbookHits = 0;
    for (double ratio : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5}) {
        int outOfBound = 0, farFromReference = 0, disagreements = 0, hits = 0, undecided = 0;
        const vec3 center = s.unitVector();   // distance 1 from the origin
        const float radius = float(ratio);
        for (int i = 0; i < 20000; ++i) {
            const bool grazing = i % 2 == 0;
            // A point at distance rho from the centre, across the line of sight.
            const Frame f = frameFromNormal(normalize(center));
            const float angle = 2 * PI * s.next();
            const float rho = grazing ? radius * (1.0f + 1e-4f * (2 * s.next() - 1)) : radius * 1.2f * std::sqrt(s.next());
            const vec3 target = center + rho * (std::cos(angle) * f.t + std::sin(angle) * f.b);
            const Ray ray(vec3(0.0f), target);
            const glm::dvec3 d = glm::normalize(glm::dvec3(target)), c(center);
            const double along = glm::dot(c, d);
            const double perp2 = glm::dot(c, c) - along * along;
            const double r2 = double(radius) * double(radius);
            const bool refHit = perp2 < r2;
            const float t = intersectSphere(ray, center, radius, 0.0f, FLOAT_MAX);
            // Within float rounding of the silhouette either answer is right: the distance from
            // the centre to the line is computed from coordinates of size 1 (16 ulps of 1).
            const bool decided = std::abs(std::sqrt(perp2) - double(radius)) > 1e-6;
            undecided += !decided;
            if (decided && (t > 0.0f) != refHit) ++disagreements;
            if (refHit) {
                const double halfChord = std::sqrt(std::max(0.0, r2 - perp2));
                const glm::dvec3 pRef = (along - halfChord) * d;
                const glm::dvec3 pRefOnSphere = c + double(radius) * glm::normalize(pRef - c);
                const double bound = sphereHitPointBound(glm::dvec3(0.0), c, double(radius), halfChord / double(radius));
                if (t > 0.0f) {
                    ++hits;
                    const vec3 p = sphereSurfacePoint(rayAt(ray, t), center, radius);
                    // The re-projected point must lie on the sphere within the error bound.
                    const double radial = std::abs(glm::length(glm::dvec3(p) - c) - double(radius));
                    if (radial > double(glm::length(sphereHitError(center, radius)))) ++outOfBound;
                    const double error = glm::length(glm::dvec3(p) - pRefOnSphere);
                    if (error > bound) ++farFromReference;
                    worstRelativeError = std::max(worstRelativeError, error / double(radius));
                    worstOfBound = std::max(worstOfBound, error / bound);
                }
                // The textbook form, t = (b − √(b² − a·c)) / a with c = |f|² − r², in float.
                const float a = dot(ray.dir, ray.dir), b = dot(center, ray.dir);
                const float disc = b * b - a * (dot(center, center) - radius * radius);
                if (disc >= 0.0f) {
                    ++textbookHits;
                    const vec3 p = sphereSurfacePoint(rayAt(ray, (b - std::sqrt(disc)) / a), center, radius);
                    textbookOutOfBound += glm::length(glm::dvec3(p) - pRefOnSphere) > bound;
                }
            }
        }
        EXPECT_EQ(disagreements, 0) << "r/d = " << ratio;
        EXPECT_EQ(outOfBound, 0) << "r/d = " << ratio;
        EXPECT_EQ(farFromReference, 0) << "r/d = " << ratio;
        EXPECT_GT(hits, 1000) << "r/d = " << ratio;
        RecordProperty("undecided_at_" + std::to_string(ratio), undecided);
    }
    // Distance between the float and the double hit point, relative to the radius and to its
    // bound: reported. It grows near the silhouette, where a tiny change of the line moves the hit
    // point far along the sphere.
    RecordProperty("worst_relative_hit_point_error", std::to_string(worstRelativeError));
    RecordProperty("worst_hit_point_error_over_bound", std::to_string(worstOfBound));
    std::printf("sphere vs double: worst hit-point distance / radius = %.3g, / its bound = %.3g; "
                "textbook quadratic: %d of %d hits out of bound\n",
                worstRelativeError, worstOfBound, textbookOutOfBound, textbookHits);
    EXPECT_GT(textbookOutOfBound, 100) << "of " << textbookHits;
}

namespace {

// A closed triangulated sphere (UV sphere, vertices jittered along the radius), as one mesh.
raylab::Scene closedSphereScene(int rings, int segments, std::uint32_t seed) {
    raylab::Scene scene;
    scene.materials.push_back(raylab::Material{});
    raylab::Mesh m;
    Sampler s{rngCreate(uvec2(seed, 1), 0u, seed)};
    m.positions.push_back(vec3(0, 1, 0));
    for (int r = 1; r < rings; ++r) {
        const float theta = PI * float(r) / float(rings);
        for (int k = 0; k < segments; ++k) {
            const float phi = 2 * PI * float(k) / float(segments);
            const float jitter = 1.0f + 0.05f * (s.next() - 0.5f);
            m.positions.push_back(jitter * vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
        }
    }
    m.positions.push_back(vec3(0, -1, 0));
    const unsigned bottom = unsigned(m.positions.size() - 1);
    auto ring = [&](int r, int k) { return unsigned(1 + (r - 1) * segments + (k % segments)); };
    for (int k = 0; k < segments; ++k) m.triangles.emplace_back(0u, ring(1, k + 1), ring(1, k));
    for (int r = 1; r < rings - 1; ++r)
        for (int k = 0; k < segments; ++k) {
            m.triangles.emplace_back(ring(r, k), ring(r, k + 1), ring(r + 1, k));
            m.triangles.emplace_back(ring(r, k + 1), ring(r + 1, k + 1), ring(r + 1, k));
        }
    for (int k = 0; k < segments; ++k) m.triangles.emplace_back(bottom, ring(rings - 1, k), ring(rings - 1, k + 1));
    scene.meshes.push_back(m);
    return scene;
}

} // namespace

TEST(IntersectionStress, NoRayEscapesAClosedMeshThroughEdgesOrVertices) {
    // 10^6 rays from points inside a closed, jittered triangulated sphere (placed by a rotation,
    // a non-uniform scale and a translation): a third aim exactly at shared vertices, a third at
    // points on shared edges, the rest in random directions. Every ray must hit the mesh
    // (through the whole BVH path: boxes, instance transform, watertight triangles).
    raylab::Scene scene = closedSphereScene(24, 48, 3);
    scene.meshes[0].transform.translation = vec3(3.0f, -2.0f, 7.0f);
    scene.meshes[0].transform.rotation = vec3(10.0f, 20.0f, 30.0f);
    scene.meshes[0].transform.scale = vec3(1.0f, 2.0f, 0.5f);
    const raylab::SceneGeometry g = raylab::buildSceneGeometry(scene);
    cpuTraversal.geometry = &g;
    const raylab::Mesh& m = scene.meshes[0];
    const glm::mat4 toWorld = raylab::transformMatrix(m.transform);
    auto world = [&](vec3 p) { return vec3(toWorld * glm::vec4(p, 1.0f)); };
    Sampler s{rngCreate(uvec2(7, 7), 0u, 7u)};
    int escaped = 0;
    const int n = 1000000;
    for (int i = 0; i < n; ++i) {
        const vec3 originLocal = 0.5f * s.unitVector() * s.next();
        const vec3 origin = world(originLocal);
        vec3 dir;
        const glm::uvec3 tri = m.triangles[std::size_t(rngNextUint(s.rng) % m.triangles.size())];
        if (i % 3 == 0) {
            dir = world(m.positions[tri[i % 2]]) - origin;   // exactly at a shared vertex
        } else if (i % 3 == 1) {
            const float a = s.next();   // a point on a shared edge
            dir = world((1.0f - a) * m.positions[tri.x] + a * m.positions[tri.y]) - origin;
        } else {
            dir = s.unitVector();
        }
        TraceRecord rec{};
        if (!traceScene(Ray(origin, dir), FLOAT_MAX, false, rec)) ++escaped;
    }
    cpuTraversal.geometry = nullptr;
    EXPECT_EQ(escaped, 0) << "of " << n << " rays";
}

TEST(IntersectionStress, WhetherATriangleIsHitDoesNotDependOnTheDirectionsLength) {
    // Scaling a direction by a power of two is exact, so the same ray must hit the same triangle
    // with t scaled by exactly the inverse. Triangles of sizes 1e-4..1e2 at 1..1e4 sizes from the
    // origin, aimed at well inside (every barycentric >= 0.1) from 10 sizes away at cosθ >= 0.1.
    Sampler s{rngCreate(uvec2(6, 7), 0u, 6u)};
    int changed = 0, tNotScaled = 0, hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const float size = s.logUniform(1e-4f, 1e2f);
        const vec3 position = s.unitVector() * (size * s.logUniform(1.0f, 1e4f));
        const vec3 p0 = position + size * s.unitVector();
        const vec3 p1 = position + size * s.unitVector();
        const vec3 p2 = position + size * s.unitVector();
        vec2 b = 0.1f + 0.8f * s.next2();
        if (b.x + b.y > 0.9f) b = 0.5f * b;
        const vec3 target = (1.0f - b.x - b.y) * p0 + b.x * p1 + b.y * p2;
        const vec3 normal = normalize(cross(p1 - p0, p2 - p0));
        vec3 back = sampleCosineHemisphere(s.next2());
        back = normalize(vec3(back.x, back.y, std::max(back.z, 0.1f)));
        const vec3 from = target + 10.0f * size * frameToWorld(frameFromNormal(normal), back);
        const vec3 dir = target - from;
        TriangleHit unit{};
        const bool hit = intersectTriangle(Ray(from, dir), p0, p1, p2, FLOAT_MAX, unit);
        hits += hit;
        for (int k = -20; k <= 20; k += 4) {
            const float scale = std::ldexp(1.0f, k);
            TriangleHit h{};
            const bool scaledHit = intersectTriangle(Ray(from, scale * dir), p0, p1, p2, FLOAT_MAX, h);
            changed += scaledHit != hit;
            tNotScaled += hit && scaledHit && h.t != unit.t / scale;
        }
    }
    EXPECT_EQ(changed, 0) << "hits that come and go with the direction's length";
    EXPECT_EQ(tNotScaled, 0);
    EXPECT_EQ(hits, 20000) << "every triangle is aimed at well inside its edges";
}

TEST(IntersectionStress, HugeCoordinatesDegenerateTrianglesAndZeroDirectionComponents) {
    Sampler s{rngCreate(uvec2(5, 5), 0u, 5u)};
    int missing = 0, nonFinite = 0, degenerateHits = 0;
    for (int i = 0; i < 20000; ++i) {
        // A unit triangle far from the origin (coordinates up to 1e6), aimed at from 10 units.
        const vec3 offset = s.unitVector() * s.logUniform(1.0f, 1e6f);
        const vec3 p0 = offset + s.unitVector(), p1 = offset + s.unitVector(), p2 = offset + s.unitVector();
        vec2 b = 0.1f + 0.8f * s.next2();   // well inside, away from edges
        if (b.x + b.y > 0.9f) b = 0.5f * b;
        const vec3 target = (1.0f - b.x - b.y) * p0 + b.x * p1 + b.y * p2;
        vec3 dir = -10.0f * s.unitVector();
        // Axis-aligned directions have exact zero components.
        if (i % 3 == 0) dir = vec3(0.0f, 0.0f, dir.z < 0 ? -10.0f : 10.0f);
        const Ray ray(target - dir, dir);
        TriangleHit h{};
        const float area = length(cross(p1 - p0, p2 - p0));
        const float facing = std::abs(dot(normalize(cross(p1 - p0, p2 - p0)), normalize(dir)));
        const bool hit = intersectTriangle(ray, p0, p1, p2, FLOAT_MAX, h);
        if (hit && !(std::isfinite(h.t) && std::isfinite(h.b0) && std::isfinite(h.b1) && std::isfinite(h.b2))) ++nonFinite;
        // Reference: the float ray against the float vertices in double precision; a hit is
        // demanded where it passes well inside (every barycentric > 1e-3) and not edge-on.
        const glm::dvec3 o(ray.origin), d(ray.dir), a(p0), e1 = glm::dvec3(p1) - a, e2 = glm::dvec3(p2) - a;
        const glm::dvec3 pv = glm::cross(d, e2);
        const double det = glm::dot(e1, pv);
        const glm::dvec3 tv = o - a;
        const double bu = glm::dot(tv, pv) / det;
        const glm::dvec3 qv = glm::cross(tv, e1);
        const double bv = glm::dot(d, qv) / det;
        const double cosine = std::abs(det) / (glm::length(glm::cross(e1, e2)) * glm::length(d));
        if (!hit && area > 0.1f && cosine > 0.05 && bu > 1e-3 && bv > 1e-3 && 1.0 - bu - bv > 1e-3) ++missing;
        (void)facing;
        if (hit && !finite(triangleHitError(h, p0, p1, p2))) ++nonFinite;
        // Needle (one side 1e-7 long) and zero-area triangles: never NaN; zero area never hits.
        const vec3 needle = p0 + 1e-7f * s.unitVector();
        if (intersectTriangle(ray, p0, needle, p2, FLOAT_MAX, h) &&
            !(std::isfinite(h.t) && std::isfinite(h.b1) && std::isfinite(h.b2)))
            ++nonFinite;
        degenerateHits += intersectTriangle(ray, p0, p0, p2, FLOAT_MAX, h);
        degenerateHits += intersectTriangle(ray, p0, 0.5f * (p0 + p2), p2, FLOAT_MAX, h) && h.t != h.t;
    }
    EXPECT_EQ(missing, 0);
    EXPECT_EQ(nonFinite, 0);
    EXPECT_EQ(degenerateHits, 0);
}

TEST(IntersectionStress, HugeCoordinateSpheresAreHitAndLeftWithoutSelfHits) {
    // Unit spheres with centres up to 10^6 from the origin (floats 0.0625 apart there), aimed at
    // from 10 units at cosθ ≥ 0.1, axis-aligned directions (exact zero components) in a third of
    // the cases: no NaN or Inf in t, the hit point or its error bound; a hit wherever the float
    // ray passes within 0.999 r of the centre in double precision; and a ray leaving the offset
    // hit point outwards (a quarter of them grazing) never hits the sphere again.
    Sampler s{rngCreate(uvec2(9, 5), 0u, 9u)};
    int missing = 0, nonFinite = 0, selfHits = 0, demanded = 0;
    for (int i = 0; i < 20000; ++i) {
        const vec3 centre = s.unitVector() * s.logUniform(1.0f, 1e6f);
        const float radius = 1.0f;
        const vec3 normal = s.unitVector();
        const vec3 target = centre + radius * normal;
        vec3 back = sampleCosineHemisphere(s.next2());
        back = normalize(vec3(back.x, back.y, std::max(back.z, 0.1f)));
        vec3 dir = -10.0f * frameToWorld(frameFromNormal(normal), back);
        if (i % 3 == 0) {   // along the axis nearest to the ray: two zero components
            const vec3 a = abs(dir);
            const int k = a.x > a.y && a.x > a.z ? 0 : (a.y > a.z ? 1 : 2);
            const float sign = dir[k] < 0.0f ? -10.0f : 10.0f;
            dir = vec3(0.0f);
            dir[k] = sign;
        }
        const Ray ray(target - dir, dir);
        const glm::dvec3 f = glm::dvec3(ray.origin) - glm::dvec3(centre), d = glm::normalize(glm::dvec3(ray.dir));
        const bool mustHit = glm::length(f - glm::dot(f, d) * d) < 0.999 * radius && glm::dot(f, d) < 0.0;
        demanded += mustHit;
        const float t = intersectSphere(ray, centre, radius, 0.0f, FLOAT_MAX);
        if (std::isnan(t) || std::isinf(t)) ++nonFinite;
        if (!(t > 0.0f)) {
            missing += mustHit;
            continue;
        }
        const vec3 p = sphereSurfacePoint(rayAt(ray, t), centre, radius);
        const vec3 n = normalize(p - centre);
        const vec3 err = sphereHitError(centre, radius);
        if (!finite(p) || !finite(n) || !finite(err)) {
            ++nonFinite;
            continue;
        }
        vec3 local = sampleCosineHemisphere(s.next2());
        if (i % 4 == 0) local = normalize(vec3(local.x, local.y, 1e-3f));   // grazing
        const Ray out(offsetRayOrigin(p, n, err), frameToWorld(frameFromNormal(n), local));
        if (!finite(out.origin)) ++nonFinite;
        selfHits += intersectSphere(out, centre, radius, 0.0f, FLOAT_MAX) > 0.0f;
    }
    EXPECT_EQ(nonFinite, 0);
    EXPECT_EQ(missing, 0) << "of " << demanded << " demanded hits";
    EXPECT_EQ(selfHits, 0);
    EXPECT_GT(demanded, 15000);
}

TEST(IntersectionStress, HugeCoordinatesThroughTheBvhHaveNoMissesNoNanAndNoSelfHits) {
    // The renderer's whole path for unit spheres and triangles up to 10^6 from the origin, placed
    // by coordinates or by translations (support/far_objects.h), in one two-level BVH: 100 rays at
    // each of 400 objects from 5 units away. A ray must find the object it was aimed at wherever
    // the double-precision verdict says it passes inside by more than float rounding can move it
    // (spheres: within 0.999 r; triangles: farther from the edges than the error bound of the
    // origin carried into object space, 0.2 units at 10^6), with nothing else in the way (objects
    // are 10 apart); t, the surface record and its error bound must be finite; a ray leaving the
    // offset hit point towards the side it came from (a quarter grazing) must not hit the same
    // primitive. The same rays through the GPU: BvhGpuTest.HugeCoordinates*.
    const raylab::Scene scene = raylab::test::farObjectsScene(400, 9);
    const raylab::SceneGeometry g = raylab::buildSceneGeometry(scene);
    cpuTraversal.geometry = &g;
    Sampler s{rngCreate(uvec2(9, 6), 0u, 9u)};
    int missing = 0, demanded = 0, demandedTriangles = 0, nonFinite = 0, selfHits = 0, left = 0;
    for (const raylab::test::AimedRay& a : raylab::test::raysAtEachObject(g, 100, 10)) {
        demanded += a.mustHit;
        demandedTriangles += a.mustHit && g.instances[a.instance].info.x == INSTANCE_MESH;
        TraceRecord rec{};
        const bool hit = traceScene(a.ray, FLOAT_MAX, false, rec);
        if (hit && !std::isfinite(rec.t)) ++nonFinite;
        if (!hit || rec.instance != a.instance) {
            missing += a.mustHit;
            continue;
        }
        const SurfaceHit surface = surfaceAt(a.ray, rec);
        if (!finite(surface.position) || !finite(surface.normal) || !finite(surface.error)) {
            ++nonFinite;
            continue;
        }
        const vec3 n = dot(surface.normal, a.ray.dir) < 0.0f ? surface.normal : -surface.normal;
        vec3 local = sampleCosineHemisphere(s.next2());
        if (left % 4 == 0) local = normalize(vec3(local.x, local.y, 1e-3f));
        const Ray out(offsetRayOrigin(surface.position, n, surface.error), frameToWorld(frameFromNormal(n), local));
        ++left;
        if (!finite(out.origin)) ++nonFinite;
        TraceRecord again{};
        selfHits += traceScene(out, FLOAT_MAX, false, again) && again.instance == rec.instance &&
                    again.primitive == rec.primitive;
    }
    cpuTraversal.geometry = nullptr;
    std::printf("huge coordinates through the BVH: %d demanded hits (%d on triangles), %d missing, %d rays left, "
                "%d self-hits\n", demanded, demandedTriangles, missing, left, selfHits);
    EXPECT_EQ(nonFinite, 0);
    EXPECT_EQ(missing, 0) << "of " << demanded << " demanded hits";
    EXPECT_EQ(selfHits, 0) << "of " << left << " rays";
    EXPECT_GT(demandedTriangles, 15000);
    EXPECT_GT(demanded, 30000);
}

TEST(IntersectionStress, BoxTestWithZeroComponentsAndOriginsOnSlabPlanes) {
    const vec3 lo(-1.0f), hi(1.0f);
    // Direction parallel to a face, origin exactly on that face's plane: inside the slab.
    EXPECT_GE(intersectBox(vec3(-5.0f, 1.0f, 0.0f), safeInverseDir(vec3(1, 0, 0)), lo, hi, FLOAT_MAX), 0.0f);
    EXPECT_GE(intersectBox(vec3(-5.0f, -1.0f, -1.0f), safeInverseDir(vec3(1, 0, 0)), lo, hi, FLOAT_MAX), 0.0f);
    EXPECT_GE(intersectBox(vec3(-5.0f, -1.0f, -1.0f), safeInverseDir(vec3(1, -0.0f, -0.0f)), lo, hi, FLOAT_MAX), 0.0f);
    // Just outside the slab, parallel: a miss.
    EXPECT_LT(intersectBox(vec3(-5.0f, 1.0000001f, 0.0f), safeInverseDir(vec3(1, 0, 0)), lo, hi, FLOAT_MAX), 0.0f);
    // Origin on a face, leaving it: t = 0 counts (the ray starts on the box).
    EXPECT_EQ(intersectBox(vec3(1.0f, 0.0f, 0.0f), safeInverseDir(vec3(1, 0, 0)), lo, hi, FLOAT_MAX), 0.0f);
    // Flat boxes (a triangle lying in a coordinate plane) with rays in that plane or across it.
    EXPECT_GE(intersectBox(vec3(0.0f, 0.0f, 5.0f), safeInverseDir(vec3(0, 0, -1)), vec3(-1, 0, -1), vec3(1, 0, 1), FLOAT_MAX), 0.0f);
    EXPECT_GE(intersectBox(vec3(0.5f, 5.0f, 0.5f), safeInverseDir(vec3(0, -1, 0)), vec3(-1, 0, -1), vec3(1, 0, 1), FLOAT_MAX), 0.0f);
    // Huge coordinates: a unit box at 1e6, grazed along its face.
    const vec3 far(1e6f);
    EXPECT_GE(intersectBox(far + vec3(-10.0f, 0.5f, 0.5f), safeInverseDir(vec3(1, 0, 0)), far, far + vec3(1.0f), FLOAT_MAX), 0.0f);
    // No NaN anywhere for random zero-component directions and on-plane origins.
    Sampler s{rngCreate(uvec2(2, 3), 0u, 1u)};
    for (int i = 0; i < 100000; ++i) {
        vec3 d = s.unitVector();
        d[i % 3] = 0.0f;
        vec3 o = 3.0f * s.unitVector();
        o[(i + 1) % 3] = (i & 4) ? 1.0f : -1.0f;   // on a slab plane
        const float t = intersectBox(o, safeInverseDir(d), lo, hi, FLOAT_MAX);
        ASSERT_FALSE(std::isnan(t)) << i;
    }
}

TEST(IntersectionStress, TransformedMeshesAndSpheresThroughTheBvhHaveNoSelfHits) {
    // The whole path the renderer takes: 200 single-triangle meshes and 200 spheres with random
    // rotations, per-axis scales over 10^±2 and translations over 10^±4, in one scene and one
    // two-level BVH; rays hit a random point, the surface record (barycentric point through the
    // instance transform, with its error bound) is offset and a new ray leaves towards the side
    // it came from. It must not hit the same primitive again. (Before the surface error bound
    // included the rounding of transforming the new origin back into object space, and before
    // that origin was moved past its own error, this found about 30 self-hits in 10^5.)
    Sampler s{rngCreate(uvec2(8, 1), 0u, 8u)};
    raylab::Scene scene;
    scene.materials.push_back(raylab::Material{});
    for (int i = 0; i < 200; ++i) {
        raylab::Mesh m;
        m.positions = {s.unitVector(), s.unitVector(), s.unitVector()};
        m.triangles = {glm::uvec3(0, 1, 2)};
        m.transform.translation = s.unitVector() * s.logUniform(1e-4f, 1e4f);
        m.transform.rotation = 360.0f * vec3(s.next(), s.next(), s.next());
        // Each axis scaled independently over 10^±2 (stretch up to 10^4:1).
        m.transform.scale = vec3(s.logUniform(1e-2f, 1e2f), s.logUniform(1e-2f, 1e2f), s.logUniform(1e-2f, 1e2f));
        scene.meshes.push_back(m);
        raylab::Sphere sp;
        sp.center = s.unitVector() * s.logUniform(1e-4f, 1e4f);
        sp.radius = s.logUniform(1e-3f, 1e3f);
        sp.transform.rotation = 360.0f * vec3(s.next(), s.next(), s.next());
        scene.spheres.push_back(sp);
    }
    const raylab::SceneGeometry g = raylab::buildSceneGeometry(scene);
    cpuTraversal.geometry = &g;
    int selfHits = 0, rays = 0;
    for (std::uint32_t inst = 0; inst < g.instances.size(); ++inst) {
        const GpuInstance& in = g.instances[inst];
        for (int i = 0; i < 250; ++i) {
            // Aim at a random point of this object from a random direction.
            vec3 target;
            float size;
            if (in.info.x == INSTANCE_SPHERE) {
                const glm::vec4 cr = g.spheres[in.info.y].centerRadius;
                target = vec3(cr) + cr.w * s.unitVector();
                size = cr.w;
            } else {
                const glm::uvec4 v = g.triangles[bvhNodeLink(g.meshNodes[in.info.y])].vertices;
                vec2 b = s.next2();
                if (b.x + b.y > 1.0f) b = vec2(1.0f) - b;
                const vec3 pObj = (1.0f - b.x - b.y) * vec3(g.vertices[v.x].positionU) + b.x * vec3(g.vertices[v.y].positionU) +
                                  b.y * vec3(g.vertices[v.z].positionU);
                target = transformPoint(in.objectToWorld0, in.objectToWorld1, in.objectToWorld2, pObj);
                size = length(transformVector(in.objectToWorld0, in.objectToWorld1, in.objectToWorld2, vec3(1.0f)));
            }
            const Ray ray(target - 3.0f * size * s.unitVector(), 3.0f * size * s.unitVector());
            TraceRecord rec{};
            if (!traceScene(Ray(target - ray.dir, ray.dir), FLOAT_MAX, false, rec)) continue;
            const Ray incoming(target - ray.dir, ray.dir);
            const SurfaceHit hit = surfaceAt(incoming, rec);
            const vec3 n = dot(hit.normal, incoming.dir) < 0.0f ? hit.normal : -hit.normal;
            vec3 local = sampleCosineHemisphere(s.next2());
            if (i % 4 == 0) local = normalize(vec3(local.x, local.y, 1e-3f));
            const Ray out(offsetRayOrigin(hit.position, n, hit.error), frameToWorld(frameFromNormal(n), local));
            TraceRecord again{};
            ++rays;
            if (traceScene(out, FLOAT_MAX, false, again) && again.instance == rec.instance &&
                again.primitive == rec.primitive) {
                // A ray leaving a sphere's inside reaches the far side after the chord 2r·cosθ; a
                // hit much nearer than that is a self-hit.
                const bool farSide = g.instances[again.instance].info.x == INSTANCE_SPHERE &&
                                     dot(hit.normal, incoming.dir) > 0.0f &&
                                     again.t > g.spheres[again.primitive].centerRadius.w * dot(out.dir, n);
                if (!farSide) ++selfHits;
            }
        }
    }
    cpuTraversal.geometry = nullptr;
    std::printf("instances through the BVH: %d rays, %d self-hits\n", rays, selfHits);
    EXPECT_EQ(selfHits, 0) << "of " << rays << " rays";
    EXPECT_GT(rays, 50000);
}
