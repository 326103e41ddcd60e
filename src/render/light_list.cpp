#include "render/light_list.h"

#include "scene/transform.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raylab {
namespace {

double luminance(glm::vec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

bool emits(glm::vec3 radiance) { return std::max({radiance.r, radiance.g, radiance.b}) > 0.0f; }

} // namespace

double sphereLightPower(glm::vec3 radiance, float radius) {
    return luminance(radiance) * 4.0 * 3.14159265358979 * double(radius) * double(radius);
}

double triangleLightPower(glm::vec3 radiance, double area, bool frontOnly) {
    return luminance(radiance) * (frontOnly ? 1.0 : 2.0) * area;
}

namespace {

constexpr double kPi = 3.14159265358979;

double cosDegrees(float degrees) { return std::cos(double(degrees) * kPi / 180.0); }

// Solid angle of a spot's cone up to 2π, as pbrt-v4 SpotLight::Phi counts the smooth falloff:
// 1 − (cos inner + cos outer)/2.
double spotConeFactor(const Light& l) { return 1.0 - 0.5 * (cosDegrees(l.innerAngle) + cosDegrees(l.outerAngle)); }

} // namespace

glm::vec3 lightIntensity(const Light& l) {
    if (!(l.power > 0.0f) || l.type == Light::Type::Distant) return l.intensity;
    const double solid = l.type == Light::Type::Point ? 4.0 * kPi : 2.0 * kPi * spotConeFactor(l);
    return glm::vec3(float(double(l.power) / solid));
}

double analyticLightPower(const Light& l) {
    switch (l.type) {
    case Light::Type::Point: return 4.0 * luminance(lightIntensity(l));
    case Light::Type::Spot: return 2.0 * luminance(lightIntensity(l)) * spotConeFactor(l);
    case Light::Type::Distant: return luminance(l.irradiance);
    }
    return 0.0;
}

void shareDistantLights(std::vector<double>& weights, const std::vector<bool>& distant) {
    double others = 0.0, irradiance = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        (distant[i] ? irradiance : others) += weights[i];
        count += distant[i] ? 1 : 0;
    }
    if (!(others > 0.0) || !(irradiance > 0.0)) return;
    const double scale = others * double(count) / irradiance;
    for (std::size_t i = 0; i < weights.size(); ++i)
        if (distant[i]) weights[i] *= scale;
}

glsl::GpuAnalyticLight gpuAnalyticLight(const Light& l) {
    const glm::vec3 dir = glm::normalize(l.direction);
    switch (l.type) {
    case Light::Type::Point:
        return {glm::vec4(l.position, float(glsl::ANALYTIC_LIGHT_POINT)), glm::vec4(0.0f), glm::vec4(lightIntensity(l), 0.0f)};
    case Light::Type::Spot:
        return {glm::vec4(l.position, float(glsl::ANALYTIC_LIGHT_SPOT)), glm::vec4(dir, float(cosDegrees(l.outerAngle))),
                glm::vec4(lightIntensity(l), float(cosDegrees(l.innerAngle)))};
    case Light::Type::Distant: {
        // 1 − cos r as 2 sin²(r/2): no cancellation for the sun's 0.27°.
        const double s = std::sin(double(l.angularRadius) * kPi / 360.0);
        const float oneMinusCos = float(2.0 * s * s);
        const glm::vec3 emitted =
            oneMinusCos > 0.0f ? l.irradiance * glsl::distantConeRadianceScale(oneMinusCos) : l.irradiance;
        return {glm::vec4(0.0f, 0.0f, 0.0f, float(glsl::ANALYTIC_LIGHT_DISTANT)), glm::vec4(-dir, oneMinusCos),
                glm::vec4(emitted, 0.0f)};
    }
    }
    return {};
}

std::vector<glm::vec4> buildAliasTable(const std::vector<double>& weights) {
    const std::size_t n = weights.size();
    if (n >= (std::size_t(1) << 24)) throw std::length_error("alias table: more than 2^24 lights");
    double total = 0.0;
    for (double w : weights) total += w;
    std::vector<glm::vec4> table(n);
    if (n == 0) return table;
    if (!(total > 0.0)) throw std::invalid_argument("alias table: weights sum to zero");
    // Scaled so the mean is 1: entries below 1 are topped up by one entry above 1 (Vose's
    // small/large work lists); what is left over at the end is 1 up to rounding.
    std::vector<double> scaled(n);
    std::vector<std::size_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        scaled[i] = weights[i] / total * double(n);
        (scaled[i] < 1.0 ? small : large).push_back(i);
        table[i] = glm::vec4(1.0f, float(i), float(weights[i] / total), 0.0f);
    }
    while (!small.empty() && !large.empty()) {
        const std::size_t s = small.back(), l = large.back();
        small.pop_back();
        table[s].x = float(scaled[s]);
        table[s].y = float(l);
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Leftovers (rounding) keep themselves with probability 1: table[i].x stays 1.
    for (glm::vec4& e : table) e.w = table[std::size_t(e.y)].z;
    return table;
}

glm::vec3 lightRadiance(const Material& material) {
    return material.emissionTextureIndex >= 0 ? glm::vec3(0.0f) : material.radiance();
}

int triangleMaterial(const Mesh& mesh, std::size_t triangle) {
    const int own = mesh.triangleMaterials.empty() ? -1 : mesh.triangleMaterials[triangle];
    return own >= 0 ? own : mesh.material;
}

bool emitsFrontOnly(const Mesh& mesh, const Material& material) {
    return mesh.emissionSides == EmissionSides::Front || (mesh.emissionSides == EmissionSides::Gltf && !material.doubleSided);
}

namespace {

// Whether the material of any of the mesh's triangles passes `test`: one test for a mesh of one
// material, a walk over the per-triangle materials otherwise.
template <class Test>
bool anyTriangleMaterial(const Scene& scene, const Mesh& mesh, Test test) {
    auto passes = [&](int material) {
        return material >= 0 && std::size_t(material) < scene.materials.size() && test(scene.materials[std::size_t(material)]);
    };
    if (mesh.triangles.empty()) return false;
    if (mesh.triangleMaterials.empty()) return passes(mesh.material);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        if (passes(triangleMaterial(mesh, t))) return true;
    return false;
}

} // namespace

bool meshHasEmissiveTriangle(const Scene& scene, const Mesh& mesh) {
    return anyTriangleMaterial(scene, mesh, [](const Material& m) { return emits(lightRadiance(m)); });
}

bool meshHasFrontOnlyTriangle(const Scene& scene, const Mesh& mesh) {
    if (mesh.emissionSides != EmissionSides::Gltf) return mesh.emissionSides == EmissionSides::Front && !mesh.triangles.empty();
    return anyTriangleMaterial(scene, mesh, [&mesh](const Material& m) { return emitsFrontOnly(mesh, m); });
}

bool sphereIsLight(const Scene& scene, const Sphere& sphere) {
    return sphere.material >= 0 && std::size_t(sphere.material) < scene.materials.size() &&
           emits(lightRadiance(scene.materials[std::size_t(sphere.material)]));
}

bool skyMayEmit(const Sky& sky) {
    if (sky.type == Sky::Type::Map) return sky.strength > 0.0f;
    return emits(sky.strength * (sky.type == Sky::Type::Constant ? sky.color : glm::max(sky.top, sky.bottom)));
}

bool lightPowersDiffer(const Scene& scene) {
    double lo = HUGE_VAL, hi = 0.0;
    auto add = [&](double p) {
        lo = std::min(lo, p);
        hi = std::max(hi, p);
    };
    auto radianceOf = [&](int material) {
        return material >= 0 && std::size_t(material) < scene.materials.size()
                   ? lightRadiance(scene.materials[std::size_t(material)])
                   : glm::vec3(0.0f);
    };
    for (const Sphere& s : scene.spheres)
        if (emits(radianceOf(s.material))) add(sphereLightPower(radianceOf(s.material), worldSphere(s).radius));
    for (const Mesh& mesh : scene.meshes) {
        if (!meshHasEmissiveTriangle(scene, mesh)) continue;   // a camera edit comes here too: skip big dark meshes
        const glm::mat4 toWorld = transformMatrix(mesh.transform);
        for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
            const glm::uvec3& t = mesh.triangles[k];
            const int material = triangleMaterial(mesh, k);
            const glm::vec3 L = radianceOf(material);
            if (!emits(L)) continue;
            glm::dvec3 p[3];
            for (int v = 0; v < 3; ++v) p[v] = glm::dvec3(toWorld * glm::vec4(mesh.positions.at(t[v]), 1.0f));
            const double area = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
            if (area > 0.0) add(triangleLightPower(L, area, emitsFrontOnly(mesh, scene.materials[std::size_t(material)])));
        }
    }
    bool distant = false;
    for (const Light& l : scene.lights) {
        if (l.type == Light::Type::Distant) distant = true;
        else add(analyticLightPower(l));
    }
    const std::size_t lights = scene.lights.size() + (hi > 0.0 ? 1 : 0);
    if (distant && lights > 1) return true;   // its share depends on the count of lights (shareDistantLights)
    return hi > lo * 1.05;
}

LightList buildLightList(const Scene& scene, const SceneGeometry& g, const std::vector<glm::vec3>& radiance) {
    LightList list;
    list.sphereLightIndex.assign(g.spheres.size(), 0u);
    for (std::size_t k = 0; k < g.spheres.size(); ++k) {
        const glsl::GpuSphere& s = g.spheres[k];
        const glm::vec3 L = radiance.at(s.info.x);
        if (!emits(L)) continue;
        list.spheres.push_back({s.centerRadius, glm::vec4(L, 0.0f)});
        list.sphereLightIndex[k] = std::uint32_t(list.spheres.size());
        list.power.push_back(sphereLightPower(L, s.centerRadius.w));
    }
    list.triangleLightIndex.assign(g.triangles.size(), 0u);
    std::size_t first = 0;   // the mesh's first triangle in g.triangles (buildSceneGeometry's order)
    for (const Mesh& mesh : scene.meshes) {
        const std::size_t count = mesh.triangles.size();
        {
            const glm::mat4 toWorld = transformMatrix(mesh.transform);
            for (std::size_t t = first; t < first + count && t < g.triangles.size(); ++t) {
                // The triangle's own material (glTF primitives: w = 1 + material), else the mesh's.
                const std::uint32_t own = g.triangles[t].vertices.w;
                const std::size_t material = own != 0u ? std::size_t(own - 1u) : std::size_t(mesh.material);
                const bool oneSided = emitsFrontOnly(mesh, scene.materials.at(material));
                const std::uint32_t frontOnly = oneSided ? glsl::TRIANGLE_FRONT_ONLY : 0u;
                list.triangleLightIndex[t] = frontOnly;
                const glm::vec3 L = radiance.at(material);
                if (!emits(L)) continue;
                glm::vec3 p[3];
                for (int k = 0; k < 3; ++k)
                    p[k] = glm::vec3(toWorld * glm::vec4(glm::vec3(g.vertices.at(g.triangles[t].vertices[k]).positionU), 1.0f));
                const double area = 0.5 * glm::length(glm::cross(glm::dvec3(p[1] - p[0]), glm::dvec3(p[2] - p[0])));
                if (!(area > 0.0)) continue;   // never hit, never sampled
                list.triangles.push_back({glm::vec4(p[0], float(area)), glm::vec4(p[1], 0.0f), glm::vec4(p[2], 0.0f),
                                          glm::vec4(L, oneSided ? 1.0f : 0.0f)});
                list.triangleLightIndex[t] = std::uint32_t(list.triangles.size()) | frontOnly;
                list.power.push_back(triangleLightPower(L, area, oneSided));
            }
        }
        first += count;
    }
    if (first != g.triangles.size()) throw std::logic_error("light list: scene and geometry disagree on triangles");
    std::vector<bool> distant(list.power.size(), false);
    for (const Light& l : scene.lights) {
        const double power = analyticLightPower(l);
        if (!(power > 0.0)) continue;   // emits nothing: never sampled, as a black emitter
        list.analytic.push_back(gpuAnalyticLight(l));
        list.power.push_back(power);
        distant.push_back(l.type == Light::Type::Distant);
    }
    shareDistantLights(list.power, distant);
    list.aliasTable = buildAliasTable(list.power);
    return list;
}

} // namespace raylab
