#pragma once
// The lights next-event estimation picks from: emissive spheres and emissive triangles, in world
// space, each picked with probability proportional to its power through an alias table. The GPU
// side is shaders/include/light_selection.glsl.
#include "accel/scene_geometry.h"
#include "scene/scene.h"

#include "shaders/include/analytic_lights.glsl"
#include "shaders/include/scene_types.glsl"

#include <cstdint>
#include <vector>

namespace raylab {

// Emitted power up to the common factor π (Φ = π·L·A for a diffuse emitter), from the Rec. 709
// luminance of the radiance: a sphere emits from its whole surface 4πr², a triangle from both
// faces (2·area), since a ray that hits either face scores its emission, or from its front alone.
double sphereLightPower(glm::vec3 radiance, float radius);
double triangleLightPower(glm::vec3 radiance, double area, bool frontOnly = false);

// A point or spot light's intensity in W/sr: `intensity`, or `power` spread over its cone
// (pbrt-v4 PointLight/SpotLight::Phi inverted: Φ = 4πI, Φ = 2πI(1 − (cos inner + cos outer)/2)).
glm::vec3 lightIntensity(const Light& light);
// A point or spot light's power by pbrt-v4's Phi, divided by π like the emitters' above; a
// distant light's is the luminance of its irradiance, a weight among distant lights alone.
double analyticLightPower(const Light& light);
// Turns the distant lights' weights (analyticLightPower) into a share of the light choice that
// does not grow with the scene's size: n distant lights get n/(n + 1) of it, split by irradiance,
// beside 1/(n + 1) for all other lights, as pbrt-v4's BVHLightSampler gives each infinite light
// the share of all bounded ones (pbrt-v4 §12.6.3); DistantLight::Phi's π r² E, r the scene's
// bounding radius, would hand a sun over a 1000-radius floor sphere nearly every pick.
void shareDistantLights(std::vector<double>& weights, const std::vector<bool>& distant);
// The GPU record of a light (positions as given: the caller makes them camera-relative).
glsl::GpuAnalyticLight gpuAnalyticLight(const Light& light);

// The material of a mesh's triangle (original order): its own (glTF primitives), else the mesh's.
int triangleMaterial(const Mesh& mesh, std::size_t triangle);

// Whether any triangle of the mesh is a light (its material's lightRadiance is above 0): one test
// for a mesh of one material, a walk over the per-triangle materials otherwise.
bool meshHasEmissiveTriangle(const Scene& scene, const Mesh& mesh);

// Whether the mesh's triangles of `material` emit from their front alone (emission_sides front,
// or gltf with a glTF material that is not doubleSided); any triangle of the mesh does so.
bool emitsFrontOnly(const Mesh& mesh, const Material& material);
bool meshHasFrontOnlyTriangle(const Scene& scene, const Mesh& mesh);

// Whether the sphere is a light (its material's lightRadiance is above 0), as buildLightList has it.
bool sphereIsLight(const Scene& scene, const Sphere& sphere);

// Whether the sky may be a light for next-event estimation: a constant or gradient sky above 0,
// or a map (whose texels the GPU scene reads: PathTracer asks its largest texel too).
bool skyMayEmit(const Sky& sky);

// The radiance a material's surface has as a light: its emission, or 0 when an emission texture
// varies it (one radiance per light; such surfaces count through BSDF hits alone, unbiased).
glm::vec3 lightRadiance(const Material& material);

// Walker's alias method (Vose 1991, "A Linear Algorithm for Generating Random Numbers with a
// Given Distribution"): entry i = (q_i, alias_i, pmf_i, pmf of alias_i); pick i uniformly, keep
// it with probability q_i, else take alias_i (the last pmf saves the shader a second read).
// Weights must be ≥ 0 with a positive sum; indices are stored as floats, exact below 2^24 entries.
std::vector<glm::vec4> buildAliasTable(const std::vector<double>& weights);

struct LightList {
    std::vector<glsl::GpuLight> spheres;              // lights 0 … S−1
    std::vector<glsl::GpuTriangleLight> triangles;    // lights S … S+T−1
    std::vector<glsl::GpuAnalyticLight> analytic;     // lights S+T … (Scene::lights)
    std::vector<double> power;                        // per light, in that order (distant: its share)
    std::vector<glm::vec4> aliasTable;                // over all lights, by power
    // Per triangle of SceneGeometry::triangles: 1 + its index in `triangles`, 0 if it is no light
    // (not emissive, or no area), plus TRIANGLE_FRONT_ONLY when it emits on the front alone.
    std::vector<std::uint32_t> triangleLightIndex;
    // Per sphere of SceneGeometry::spheres: 1 + its index in `spheres`, 0 if it is no light; the
    // GPU scene writes it into the sphere's record (GpuSphere info.z).
    std::vector<std::uint32_t> sphereLightIndex;
};

// Whether the scene's lights (emissive spheres, emissive triangles with area, point and spot
// lights; a distant light beside any other counts as different) differ in power by
// more than 5% (largest / smallest). When they do not, picking uniformly is as good as picking by
// power (the variance gain is of second order in the differences), and the tracer is compiled
// without the table (RAYLAB_LIGHT_POWER_SELECTION off, render/shader_variant.h): such scenes pick
// uniformly. Any choice is unbiased: only the noise differs.
bool lightPowersDiffer(const Scene& scene);

// `radiance` per material (Material::radiance()). Triangles of a mesh are put in world space with
// its transform; the order follows `geometry` (meshes in scene order, triangles in BVH leaf order).
LightList buildLightList(const Scene& scene, const SceneGeometry& geometry, const std::vector<glm::vec3>& radiance);

} // namespace raylab
