// Checks of the intersection slots (ray–sphere, ray–triangle, the slab test) against double
// precision on fixed rays, the grazing cases and watertightness included.
#include "exercise/check_support.h"

#include "shaders/include/aabb.glsl"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace raylab {
using namespace exercise;
namespace {

using glm::dvec3;
using glm::vec3;
using glm::vec4;

constexpr double kTolerance = 1e-4;   // relative, on t; float code against double

vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> n;
    return glm::normalize(vec3(n(rng), n(rng), n(rng)));
}

// Failing case labels, in order of first appearance, "label (k)".
std::string failingLabels(const std::vector<std::string>& labels, const std::vector<bool>& wrong) {
    std::vector<std::string> order;
    std::map<std::string, int> counts;
    for (std::size_t i = 0; i < labels.size(); ++i)
        if (wrong[i] && counts[labels[i]]++ == 0) order.push_back(labels[i]);
    std::string s;
    for (const auto& l : order) s += (s.empty() ? "" : ", ") + l + " (" + std::to_string(counts[l]) + ")";
    return s;
}

// --- Ray–sphere ---------------------------------------------------------------------------------

struct SphereCase {
    vec3 origin, dir, center;
    float radius, tMin, tMax;
    std::string label;
};

std::vector<SphereCase> sphereCases() {
    std::mt19937 rng(15);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<SphereCase> cases;
    const vec3 c(0.5f, -0.25f, -5.0f);
    const float r = 1.25f;
    for (int i = 0; i < 40; ++i) {   // from outside, at a point of the sphere's front
        const vec3 o(u(rng) - 0.5f, u(rng) - 0.5f, u(rng));
        vec3 target = c + 0.98f * r * randomUnit(rng);
        cases.push_back({o, glm::normalize(target - o), c, r, 1e-4f, 1e30f, "from outside"});
    }
    for (int i = 0; i < 20; ++i) {   // from inside: the far root
        const vec3 o = c + 0.7f * r * u(rng) * randomUnit(rng);
        cases.push_back({o, randomUnit(rng), c, r, 1e-4f, 1e30f, "from inside"});
    }
    for (int i = 0; i < 20; ++i) {   // behind the origin
        const vec3 o(u(rng) - 0.5f, u(rng) - 0.5f, u(rng));
        const vec3 target = c + 0.9f * r * randomUnit(rng);
        cases.push_back({o, -glm::normalize(target - o), c, r, 1e-4f, 1e30f, "sphere behind the ray"});
    }
    for (int i = 0; i < 20; ++i) {   // grazing: passing at (1 ± 1e-3)·r from the centre
        const vec3 o(u(rng) - 0.5f, u(rng) - 0.5f, u(rng));
        const vec3 toC = glm::normalize(c - o);
        vec3 side = glm::normalize(glm::cross(toC, randomUnit(rng)));
        const bool hit = i % 2 == 0;
        const float d = r * (hit ? 1.0f - 1e-3f : 1.0f + 1e-3f);
        // Aim at the point beside the centre at distance d, perpendicular to the ray.
        const vec3 target = c + d * side;
        cases.push_back({o, glm::normalize(target - o), c, r, 1e-4f, 1e30f, hit ? "grazing hit" : "grazing miss"});
    }
    for (int i = 0; i < 20; ++i) {   // a clear miss
        const vec3 o(u(rng) - 0.5f, u(rng) - 0.5f, u(rng));
        const vec3 target = c + (1.5f + u(rng)) * r * glm::normalize(glm::cross(c - o, randomUnit(rng)));
        cases.push_back({o, glm::normalize(target - o), c, r, 1e-4f, 1e30f, "miss"});
    }
    for (int i = 0; i < 20; ++i) {   // the hit lies beyond tMax; or the near root before tMin
        const vec3 o(u(rng) - 0.5f, u(rng) - 0.5f, u(rng));
        const vec3 target = c + 0.5f * r * randomUnit(rng);
        const float dist = glm::length(c - o);
        if (i % 2 == 0)
            cases.push_back({o, glm::normalize(target - o), c, r, 1e-4f, 0.5f * dist, "beyond tMax"});
        else
            cases.push_back({o, glm::normalize(target - o), c, r, dist, 1e30f, "near root before tMin"});
    }
    return cases;
}

struct Roots {
    bool real = false;
    double t0 = 0.0, t1 = 0.0;
};

Roots sphereRoots(const SphereCase& s) {
    const dvec3 o(s.origin), d(s.dir), c(s.center);
    const dvec3 oc = o - c;
    const double a = glm::dot(d, d);
    const double hb = glm::dot(oc, d);
    const double cc = glm::dot(oc, oc) - double(s.radius) * double(s.radius);
    const double disc = hb * hb - a * cc;
    if (disc < 0.0) return {};
    return {true, (-hb - std::sqrt(disc)) / a, (-hb + std::sqrt(disc)) / a};
}

bool inRange(double t, const SphereCase& s) { return t > double(s.tMin) && t < double(s.tMax); }

} // namespace

CheckResult checkSphereRays(const ExerciseProbe& probe) {
    const auto cases = sphereCases();
    std::vector<ProbeInput> in;
    for (const auto& s : cases)
        in.push_back({{vec4(s.origin, s.tMin), vec4(s.dir, s.tMax), vec4(s.center, s.radius), vec4(0), vec4(0), vec4(0)}});
    const auto out = probe.run(ProbeMode::Sphere, in);
    std::vector<double> got, want;
    std::vector<std::string> labels;
    Mistake far{"returns the far root (−b + √Δ)/2a where the near root (−b − √Δ)/2a counts", {}};
    Mistake noTMin{"returns hits at t ≤ tMin, behind the ray: test t > tMin before returning it", {}};
    Mistake noInside{"misses from inside the sphere: when the near root is ≤ tMin the far root counts", {}};
    Mistake noTMax{"returns hits beyond tMax: test t < tMax too", {}};
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& s = cases[i];
        const Roots r = sphereRoots(s);
        got.push_back(out[i].a.x);
        labels.push_back(s.label);
        const double miss = -1.0;
        want.push_back(!r.real ? miss : inRange(r.t0, s) ? r.t0 : inRange(r.t1, s) ? r.t1 : miss);
        far.values.push_back(!r.real ? miss : inRange(r.t1, s) ? r.t1 : inRange(r.t0, s) ? r.t0 : miss);
        noTMin.values.push_back(!r.real ? miss : r.t0 < double(s.tMax) ? r.t0 : r.t1 < double(s.tMax) ? r.t1 : miss);
        noInside.values.push_back(!r.real ? miss : inRange(r.t0, s) ? r.t0 : miss);
        noTMax.values.push_back(!r.real ? miss : r.t0 > double(s.tMin) ? r.t0 : r.t1 > double(s.tMin) ? r.t1 : miss);
    }
    const Comparison c = compare(got, want, kTolerance);
    CheckResult res{"sphere-rays", c.wrong == 0, describe(c, "rays"), "", ""};
    if (!res.pass) {
        std::vector<bool> wrong(got.size());
        for (std::size_t i = 0; i < got.size(); ++i) wrong[i] = !agrees(got[i], want[i], kTolerance);
        const auto& s = cases[std::size_t(c.firstWrong)];
        res.message = "wrong for: " + failingLabels(labels, wrong) + "; e.g. origin (" + num(s.origin.x) + ", " +
                      num(s.origin.y) + ", " + num(s.origin.z) + ") expects t = " + num(want[std::size_t(c.firstWrong)]) +
                      ", got " + num(got[std::size_t(c.firstWrong)]);
        const std::string why = diagnose(got, {far, noTMin, noInside, noTMax}, kTolerance);
        if (!why.empty()) res.message = "ray-sphere: " + why + " (" + res.message + ")";
    }
    return res;
}

// --- Ray–triangle -------------------------------------------------------------------------------
namespace {

struct TriangleCase {
    vec3 origin, dir, p0, p1, p2;
    float tMax;
    std::string label;
};

struct TriangleTruth {
    bool hit = false;
    double t = 0.0, b1 = 0.0, b2 = 0.0;
    double det = 0.0;   // > 0: the front (counter-clockwise seen from the origin)
};

TriangleTruth triangleTruth(const TriangleCase& c) {
    const dvec3 o(c.origin), d(c.dir), p0(c.p0), e1 = dvec3(c.p1) - p0, e2 = dvec3(c.p2) - p0;
    const dvec3 p = glm::cross(d, e2);
    TriangleTruth t;
    t.det = glm::dot(e1, p);
    if (t.det == 0.0) return t;
    const dvec3 s = o - p0;
    const double u = glm::dot(s, p) / t.det;
    const dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / t.det;
    t.t = glm::dot(e2, q) / t.det;
    t.b1 = u;
    t.b2 = v;
    t.hit = u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t.t > 0.0 && t.t < double(c.tMax);
    return t;
}

std::vector<TriangleCase> triangleCases() {
    std::mt19937 rng(16);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<TriangleCase> cases;
    for (int i = 0; i < 120; ++i) {
        const vec3 centre = vec3(0.0f, 0.0f, -3.0f) + 0.5f * randomUnit(rng);
        vec3 p0 = centre + randomUnit(rng), p1 = centre + randomUnit(rng), p2 = centre + randomUnit(rng);
        if (i % 2 == 1) std::swap(p1, p2);   // the other side faces the origin
        const vec3 o(0.3f * (u(rng) - 0.5f), 0.3f * (u(rng) - 0.5f), 0.0f);
        const int kind = i % 6;
        float b1 = u(rng), b2 = u(rng);
        if (kind < 3 && b1 + b2 > 1.0f) {
            b1 = 1.0f - b1;
            b2 = 1.0f - b2;
        }
        if (kind == 3) b1 = 1.05f + u(rng);   // outside, past edge p0 p2
        b1 = std::clamp(b1, 0.02f, 3.0f);
        b2 = kind < 3 ? std::clamp(b2, 0.02f, 0.98f - b1) : b2;
        const vec3 target = p0 + b1 * (p1 - p0) + b2 * (p2 - p0);
        vec3 dir = glm::normalize(target - o);
        float tMax = 1e30f;
        std::string label = (i % 2 == 0) ? "hit" : "hit from the back";
        if (kind == 3) label = "miss beside the triangle";
        if (kind == 4) {
            dir = -dir;
            label = "triangle behind the ray";
        }
        if (kind == 5) {
            tMax = 0.5f * glm::length(target - o);
            label = "beyond tMax";
        }
        cases.push_back({o, dir, p0, p1, p2, tMax, label});
    }
    return cases;
}

std::vector<ProbeOutput> runTriangles(const ExerciseProbe& probe, const std::vector<TriangleCase>& cases) {
    std::vector<ProbeInput> in;
    for (const auto& c : cases)
        in.push_back({{vec4(c.origin, c.tMax), vec4(c.dir, 0.0f), vec4(c.p0, 0.0f), vec4(c.p1, 0.0f), vec4(c.p2, 0.0f), vec4(0)}});
    return probe.run(ProbeMode::Triangle, in);
}

} // namespace

CheckResult checkTriangleRays(const ExerciseProbe& probe) {
    const auto cases = triangleCases();
    const auto out = runTriangles(probe, cases);
    std::vector<double> gotHit, wantHit, gotValues, wantValues;
    std::vector<std::string> labels;
    Mistake culls{"misses triangles seen from the back (det < 0): both sides count, test det ≠ 0", {}};
    Mistake behind{"hits triangles behind the ray's origin: test t > 0", {}};
    Mistake noTMax{"hits beyond tMax: test t < tMax", {}};
    Mistake swapped{"barycentrics swapped: b1 weights p1 (u, along p1 − p0) and b2 weights p2 (v)", {}};
    std::vector<double> swappedValues;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const TriangleTruth t = triangleTruth(cases[i]);
        const bool inside = t.b1 >= 0.0 && t.b2 >= 0.0 && t.b1 + t.b2 <= 1.0;
        labels.push_back(cases[i].label);
        gotHit.push_back(out[i].a.x > 0.5f ? 1.0 : 0.0);
        wantHit.push_back(t.hit ? 1.0 : 0.0);
        culls.values.push_back(t.hit && t.det > 0.0 ? 1.0 : 0.0);
        behind.values.push_back(inside && t.t != 0.0 && t.t < double(cases[i].tMax) ? 1.0 : 0.0);
        noTMax.values.push_back(inside && t.t > 0.0 ? 1.0 : 0.0);
        if (t.hit && out[i].a.x > 0.5f) {
            for (double g : {double(out[i].a.y), double(out[i].a.z), double(out[i].a.w)}) gotValues.push_back(g);
            for (double w : {t.t, t.b1, t.b2}) wantValues.push_back(w);
            for (double w : {t.t, t.b2, t.b1}) swapped.values.push_back(w);
        }
    }
    const Comparison hits = compare(gotHit, wantHit, 0.0);
    const Comparison values = compare(gotValues, wantValues, kTolerance);
    CheckResult res{"triangle-rays", hits.wrong == 0 && values.wrong == 0,
                    describe(hits, "hit/miss answers") + "; " + describe(values, "t and barycentric values"), "", ""};
    if (res.pass) return res;
    if (hits.wrong > 0) {
        std::vector<bool> wrong(gotHit.size());
        for (std::size_t i = 0; i < gotHit.size(); ++i) wrong[i] = gotHit[i] != wantHit[i];
        res.message = "wrong hit/miss for: " + failingLabels(labels, wrong);
        const std::string why = diagnose(gotHit, {culls, behind, noTMax}, 0.0);
        if (!why.empty()) res.message = "ray-triangle: " + why + " (" + res.message + ")";
    } else {
        res.message = "t or barycentrics differ from double precision";
        const std::string why = diagnose(gotValues, {swapped}, kTolerance);
        if (!why.empty()) res.message = "ray-triangle: " + why;
    }
    return res;
}

CheckResult checkWatertight(const ExerciseProbe& probe) {
    // An 8 × 8 grid of squares, each split along its diagonal, in z = 0; rays straight down through
    // the midpoints of shared edges and through shared vertices, each tested against the triangles
    // that share the point. Coordinates are multiples of 1/8, so a correct edge test is exact here.
    const int n = 8;
    auto vertex = [&](int i, int j) { return vec3(float(i) / n, float(j) / n, 0.0f); };
    struct Tri {
        vec3 p0, p1, p2;
    };
    // Triangles of cell (i, j): (a, b, c) and (a, c, d), a the lower-left corner.
    auto cellTris = [&](int i, int j) {
        const vec3 a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
        return std::array<Tri, 2>{Tri{a, b, c}, Tri{a, c, d}};
    };
    std::vector<std::vector<Tri>> groups;   // per ray: the triangles around its point
    std::vector<vec3> points;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const auto t = cellTris(i, j);
            points.push_back(0.5f * (vertex(i, j) + vertex(i + 1, j + 1)));   // the diagonal's midpoint
            groups.push_back({t[0], t[1]});
            if (i + 1 < n) {   // the vertical edge to the right neighbour
                const auto r = cellTris(i + 1, j);
                points.push_back(0.5f * (vertex(i + 1, j) + vertex(i + 1, j + 1)));
                groups.push_back({t[0], r[1]});
            }
            if (j + 1 < n) {   // the horizontal edge to the upper neighbour
                const auto u = cellTris(i, j + 1);
                points.push_back(0.5f * (vertex(i, j + 1) + vertex(i + 1, j + 1)));
                groups.push_back({t[1], u[0]});
            }
            if (i + 1 < n && j + 1 < n) {   // the shared vertex at the cell's upper-right corner
                std::vector<Tri> around;
                for (int di = 0; di < 2; ++di)
                    for (int dj = 0; dj < 2; ++dj)
                        for (const Tri& tri : cellTris(i + di, j + dj)) around.push_back(tri);
                points.push_back(vertex(i + 1, j + 1));
                groups.push_back(around);
            }
        }
    std::vector<TriangleCase> cases;
    std::vector<std::size_t> owner;
    for (std::size_t r = 0; r < points.size(); ++r)
        for (const Tri& t : groups[r]) {
            cases.push_back({points[r] + vec3(0.0f, 0.0f, 1.0f), vec3(0.0f, 0.0f, -1.0f), t.p0, t.p1, t.p2, 1e30f, ""});
            owner.push_back(r);
        }
    const auto out = runTriangles(probe, cases);
    std::vector<bool> hit(points.size(), false);
    for (std::size_t k = 0; k < cases.size(); ++k)
        if (out[k].a.x > 0.5f) hit[owner[k]] = true;
    const auto cracks = std::count(hit.begin(), hit.end(), false);
    CheckResult res{"watertight", cracks == 0,
                    std::to_string(cracks) + " of " + std::to_string(points.size()) +
                        " rays through shared edges and vertices hit no triangle",
                    "", ""};
    if (!res.pass)
        res.message = "ray-triangle: rays through an edge shared by two triangles hit neither: a point on an edge must "
                      "count (u ≥ 0, v ≥ 0, u + v ≤ 1, not > 0 and < 1)";
    return res;
}

// --- The slab test ------------------------------------------------------------------------------
namespace {

struct BoxCase {
    vec3 origin, dir;
    float tMax;
    std::string label;
};

const vec3 kBoxMin(-1.0f, 0.5f, -4.0f);
const vec3 kBoxMax(1.5f, 2.0f, -2.0f);

// Entry and exit of the ray through the slabs, in double; noSwap keeps (min − o)/d as the near end.
struct Slabs {
    double enter, leave;
};
Slabs slabs(const BoxCase& c, bool swap) {
    double enter = -1e300, leave = 1e300;
    for (int k = 0; k < 3; ++k) {
        const double o = c.origin[k], d = c.dir[k], lo = kBoxMin[k], hi = kBoxMax[k];
        if (d == 0.0) {
            if (o < lo || o > hi) return {1.0, 0.0};
            continue;
        }
        double t0 = (lo - o) / d, t1 = (hi - o) / d;
        if (swap && t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    return {enter, leave};
}

std::vector<BoxCase> boxCases() {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<BoxCase> cases;
    auto inBox = [&](float margin) {
        return kBoxMin + margin + vec3(u(rng), u(rng), u(rng)) * (kBoxMax - kBoxMin - 2.0f * margin);
    };
    for (int i = 0; i < 60; ++i) {   // from outside on every side, into the box
        const vec3 o = 0.5f * (kBoxMin + kBoxMax) + (4.0f + 2.0f * u(rng)) * randomUnit(rng);
        cases.push_back({o, glm::normalize(inBox(0.05f) - o), 1e30f, "hit from outside"});
    }
    for (int i = 0; i < 20; ++i) cases.push_back({inBox(0.05f), randomUnit(rng), 1e30f, "origin inside"});
    for (int i = 0; i < 20; ++i) {   // away from the box
        const vec3 o = 0.5f * (kBoxMin + kBoxMax) + (4.0f + 2.0f * u(rng)) * randomUnit(rng);
        cases.push_back({o, -glm::normalize(inBox(0.05f) - o), 1e30f, "box behind the ray"});
    }
    for (int i = 0; i < 20; ++i) {   // axis-parallel, through and beside the box
        const int axis = i % 3;
        vec3 o = inBox(0.05f);
        vec3 d(0.0f);
        d[axis] = (i % 2 == 0) ? 1.0f : -1.0f;
        o[axis] = d[axis] > 0.0f ? kBoxMin[axis] - 2.0f : kBoxMax[axis] + 2.0f;
        if (i % 4 == 3) o[(axis + 1) % 3] = kBoxMax[(axis + 1) % 3] + 0.5f;
        cases.push_back({o, d, 1e30f, i % 4 == 3 ? "axis-parallel miss" : "axis-parallel hit"});
    }
    for (int i = 0; i < 20; ++i) {   // the box beyond tMax
        const vec3 o = 0.5f * (kBoxMin + kBoxMax) + 5.0f * randomUnit(rng);
        cases.push_back({o, glm::normalize(inBox(0.05f) - o), 1.5f, "box beyond tMax"});
    }
    return cases;
}

} // namespace

CheckResult checkBoxRays(const ExerciseProbe& probe) {
    const auto cases = boxCases();
    std::vector<ProbeInput> in;
    for (const auto& c : cases)
        in.push_back({{vec4(c.origin, c.tMax), vec4(glsl::safeInverseDir(c.dir), 0.0f), vec4(kBoxMin, 0.0f),
                       vec4(kBoxMax, 0.0f), vec4(0), vec4(0)}});
    const auto out = probe.run(ProbeMode::Box, in);
    std::vector<double> got, want;
    std::vector<std::string> labels;
    Mistake noSwap{"misses rays with negative direction components: swap t0 and t1 per axis (tNear = min, tFar = max)", {}};
    Mistake noClamp{"returns a negative entry when the origin is inside the box: the interval starts at t = 0", {}};
    Mistake exit{"returns where the ray leaves the box, not where it enters", {}};
    Mistake noTMax{"hits boxes beyond tMax: the interval ends at tMax", {}};
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& c = cases[i];
        const double tMax = c.tMax;
        const Slabs s = slabs(c, true), n = slabs(c, false);
        // What `enter <= leave ? enter : -1` returns, with or without the clamp to [0, tMax].
        auto entry = [&](Slabs sl, bool clamp, bool useTMax) {
            const double e = clamp ? std::max(sl.enter, 0.0) : sl.enter;
            const double l = useTMax ? std::min(sl.leave, tMax) : sl.leave;
            return e <= l ? e : -1.0;
        };
        got.push_back(out[i].a.x);
        labels.push_back(c.label);
        want.push_back(entry(s, true, true));
        noSwap.values.push_back(entry(n, true, true));
        noClamp.values.push_back(entry(s, false, true));
        const double e = std::max(s.enter, 0.0), l = std::min(s.leave, tMax);
        exit.values.push_back(e <= l ? l : -1.0);
        noTMax.values.push_back(entry(s, true, false));
    }
    const Comparison c = compare(got, want, kTolerance);
    CheckResult res{"box-rays", c.wrong == 0, describe(c, "rays"), "", ""};
    if (!res.pass) {
        std::vector<bool> wrong(got.size());
        for (std::size_t i = 0; i < got.size(); ++i) wrong[i] = !agrees(got[i], want[i], kTolerance);
        res.message = "wrong for: " + failingLabels(labels, wrong);
        const std::string why = diagnose(got, {noSwap, noClamp, exit, noTMax}, kTolerance);
        if (!why.empty()) res.message = "slab test: " + why + " (" + res.message + ")";
    }
    return res;
}

} // namespace raylab
