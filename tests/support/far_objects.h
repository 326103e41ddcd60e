#pragma once
// Unit-size objects far from the origin (coordinates up to 10^6) for the stress tests of the whole
// traversal (the shader's code on the CPU: shaders/intersection_stress_test.cpp; on the GPU:
// accel/bvh_test.cpp), and rays aimed at each with a double-precision verdict on whether they
// must hit it.
#include "accel/scene_geometry.h"
#include "scene/scene.h"
#include "shaders/include/frame.glsl"
#include "shaders/include/instance_transform.glsl"
#include "shaders/include/ray.glsl"
#include "shaders/include/sampling.glsl"
#include "support/stress_sampler.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace raylab::test {

// `count` objects, alternately spheres of radius 1 and equilateral triangles of circumradius 1,
// their centres log-uniform in distance from 1 to 10^6 and at least 10 apart. Every other pair is
// placed by its coordinates (a sphere's centre, a triangle's vertices), the others by a
// translation (a rotation too for triangles), so both the object-space and the world-space
// paths see huge numbers.
inline Scene farObjectsScene(int count, std::uint32_t seed) {
    StressSampler s{glsl::rngCreate(glm::uvec2(seed, 11u), 0u, seed)};
    Scene scene;
    scene.materials.push_back(Material{});
    std::vector<glm::vec3> centres;
    while (int(centres.size()) < count) {
        const glm::vec3 c = s.unitVector() * s.logUniform(1.0f, 1e6f);
        bool apart = true;
        for (const glm::vec3& o : centres) apart = apart && glm::distance(o, c) >= 10.0f;
        if (!apart) continue;
        const int i = int(centres.size());
        centres.push_back(c);
        const bool byTransform = (i / 2) % 2 == 1;
        if (i % 2 == 0) {
            Sphere sp;
            sp.radius = 1.0f;
            (byTransform ? sp.transform.translation : sp.center) = c;
            scene.spheres.push_back(sp);
        } else {
            Mesh m;
            const glsl::Frame f = glsl::frameFromNormal(s.unitVector());
            for (int k = 0; k < 3; ++k) {
                const float a = 2.0f * glsl::PI * float(k) / 3.0f;
                const glm::vec3 p = std::cos(a) * f.t + std::sin(a) * f.b;
                m.positions.push_back(byTransform ? p : c + p);
            }
            m.triangles = {glm::uvec3(0, 1, 2)};
            if (byTransform) {
                m.transform.translation = c;
                m.transform.rotation = 360.0f * glm::vec3(s.next(), s.next(), s.next());
            }
            scene.meshes.push_back(m);
        }
    }
    return scene;
}

struct AimedRay {
    glsl::Ray ray;
    std::uint32_t instance;   // the object aimed at
    bool mustHit;             // in double precision the ray passes well inside that object
};

// `perObject` rays at random points of each instance of g, from 5 units away, arriving at
// cosθ ≥ 0.2 (triangles from either side). The verdict is the float ray against the object as
// stored (a sphere's world centre; a triangle's object-space vertices through the instance's
// object-to-world matrix), in double: a sphere must be hit where the line passes within
// 0.999 r of its centre, a triangle where it passes inside by more than the rounding error of the
// ray's origin carried into object space (below).
inline std::vector<AimedRay> raysAtEachObject(const SceneGeometry& g, int perObject, std::uint32_t seed) {
    StressSampler s{glsl::rngCreate(glm::uvec2(seed, 12u), 0u, seed)};
    std::vector<AimedRay> rays;
    for (std::uint32_t inst = 0; inst < g.instances.size(); ++inst) {
        const glsl::GpuInstance& in = g.instances[inst];
        const bool sphere = in.info.x == glsl::INSTANCE_SPHERE;
        glm::vec3 v[3];
        if (!sphere) {
            const glm::uvec4 tri = g.triangles[glsl::bvhNodeLink(g.meshNodes[in.info.y])].vertices;
            for (int k = 0; k < 3; ++k) v[k] = glm::vec3(g.vertices[tri[k]].positionU);
        }
        // The object-to-world map in double: x ↦ M·x + t, from the stored float rows.
        const glm::dmat3 M = glm::transpose(glm::dmat3(glm::dvec3(in.objectToWorld0), glm::dvec3(in.objectToWorld1),
                                                       glm::dvec3(in.objectToWorld2)));
        const glm::dvec3 t(in.objectToWorld0.w, in.objectToWorld1.w, in.objectToWorld2.w);
        const glm::dmat3 Minv = glm::inverse(M);
        for (int i = 0; i < perObject; ++i) {
            glm::vec3 target, facing;
            if (sphere) {
                const glm::vec4 cr = g.spheres[in.info.y].centerRadius;
                facing = s.unitVector();
                target = glm::vec3(cr) + cr.w * facing;
            } else {
                glm::vec2 b = s.next2();
                if (b.x + b.y > 1.0f) b = glm::vec2(1.0f) - b;
                const glm::vec3 p = (1.0f - b.x - b.y) * v[0] + b.x * v[1] + b.y * v[2];
                target = glsl::transformPoint(in.objectToWorld0, in.objectToWorld1, in.objectToWorld2, p);
                const glm::vec3 e1 = glsl::transformVector(in.objectToWorld0, in.objectToWorld1, in.objectToWorld2, v[1] - v[0]);
                const glm::vec3 e2 = glsl::transformVector(in.objectToWorld0, in.objectToWorld1, in.objectToWorld2, v[2] - v[0]);
                facing = glm::normalize(glm::cross(e1, e2)) * (i % 2 ? -1.0f : 1.0f);
            }
            glm::vec3 back = glsl::sampleCosineHemisphere(s.next2());
            back = glm::normalize(glm::vec3(back.x, back.y, std::max(back.z, 0.2f)));
            const glm::vec3 from = target + 5.0f * glsl::frameToWorld(glsl::frameFromNormal(facing), back);
            const glsl::Ray ray(from, target - from);
            bool mustHit = false;
            if (sphere) {
                const glm::dvec4 cr(g.spheres[in.info.y].centerRadius);
                const glm::dvec3 f = glm::dvec3(ray.origin) - glm::dvec3(cr), d = glm::normalize(glm::dvec3(ray.dir));
                const glm::dvec3 perp = f - glm::dot(f, d) * d;
                mustHit = glm::length(perp) < 0.999 * cr.w && glm::dot(f, d) < 0.0;
            } else {
                const glm::dvec3 o = Minv * (glm::dvec3(ray.origin) - t), d = Minv * glm::dvec3(ray.dir);
                const glm::dvec3 a(v[0]), e1 = glm::dvec3(v[1]) - a, e2 = glm::dvec3(v[2]) - a;
                const glm::dvec3 pv = glm::cross(d, e2), tv = o - a, qv = glm::cross(tv, e1);
                const double det = glm::dot(e1, pv);
                const double bu = glm::dot(tv, pv) / det, bv = glm::dot(d, qv) / det, tHit = glm::dot(e2, qv) / det;
                // Distance from the crossing point to the nearest edge (b_k × the height over edge k).
                const double twiceArea = glm::length(glm::cross(e1, e2));
                const double edgeDistance = std::min({(1.0 - bu - bv) * twiceArea / glm::length(e2 - e1),
                                                      bu * twiceArea / glm::length(e2), bv * twiceArea / glm::length(e1)});
                // The traversal meets the triangle in object space, from an origin known within
                // transformPointError (the rounding of the world-to-object product, γ(3)·|o| per
                // coordinate: 0.2 units at 10^6) and then moved along the ray, which rounds it once
                // more: a float ray that passes closer to an edge than that may go either way.
                const glm::vec3 oObj = glsl::transformPoint(in.worldToObject0, in.worldToObject1, in.worldToObject2, ray.origin);
                const glm::vec3 oError = glsl::transformPointError(in.worldToObject0, in.worldToObject1, in.worldToObject2,
                                                                   ray.origin, glm::vec3(0.0f));
                const double tolerance = glm::length(glm::dvec3(oError)) + 2.0 * glm::length(glm::dvec3(oObj)) * 0x1p-23;
                mustHit = bu > 0.0 && bv > 0.0 && 1.0 - bu - bv > 0.0 && edgeDistance > tolerance && tHit > 0.0;
            }
            rays.push_back({ray, inst, mustHit});
        }
    }
    return rays;
}

} // namespace raylab::test
