#pragma once
// The in-memory scene: what a scene file describes, after validation. Plain data; the loader
// (scene_loader.h) fills it, the renderer reads it. Units and ranges are in scenes/FORMAT.md.
#include "texture/texture.h"
#include "shaders/include/estimator_stages.glsl"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace raylab {

// Thin-lens camera (a pinhole when aperture is 0). Right-handed, y up by default.
struct Camera {
    glm::vec3 position{0.0f, 1.0f, 6.0f}; // eye point, world units
    glm::vec3 lookAt{0.0f, 1.0f, 0.0f};   // point the view centre passes through
    glm::vec3 up{0.0f, 1.0f, 0.0f};       // approximate up; must not be parallel to the view axis
    float fovY = 40.0f;                   // vertical field of view, degrees, (0, 180)
    float aperture = 0.0f;                // lens radius, world units; 0 = pinhole
    float focusDistance = 0.0f;           // world units; 0 = the distance to lookAt
};

// How the linear image is turned into display values for PNG (EXR stays linear).
enum class ToneMap { Clamp, Reinhard, AcesFit };

// The renderer built up stage by stage, as a class watches it grow (render.stage; each stage is its
// own compiled variant, render/shader_variant.cpp). The numbers are RAYLAB_STAGE_* of features.glsl.
enum class RenderStage {
    Primary = 0,    // camera rays only: the flat albedo of the first hit (= the albedo view)
    Emission = 1,   // + emitters and sky seen directly (= max_bounces 0)
    Lambert = 2,    // + path tracing with every material Lambertian (albedo only)
    Ggx = 3,        // + GGX specular, Fresnel and glass
    Textures = 4,   // + image and normal textures
    Full = 5,       // + depth of field: everything
};

// How a path's random numbers are made (render.sampler; shaders/include/sampler.glsl). The numbers
// are RAYLAB_SAMPLER_* of features.glsl.
enum class SamplerKind {
    Independent = 0,   // hashed PCG: every number independent
    Stratified = 1,    // jittered strata per dimension, in a per-pixel random order
    Sobol = 2,         // Owen-scrambled Sobol (Burley 2020)
    ZSobol = 3,        // one Sobol sequence over Morton-ordered pixels (Ahmed & Wonka 2020)
};

// The estimator's switchable stages (shaders/include/estimator_stages.glsl, whose numbers they are).
enum class DiffuseSampling { Cosine = RAYLAB_DIFFUSE_COSINE, Uniform = RAYLAB_DIFFUSE_UNIFORM };
enum class GgxSampling { Vndf = RAYLAB_GGX_VNDF, DCos = RAYLAB_GGX_D_COS };
enum class LightSelection { Power = RAYLAB_LIGHT_SELECTION_POWER, Uniform = RAYLAB_LIGHT_SELECTION_UNIFORM };
enum class LightSampling { SolidAngle = RAYLAB_LIGHT_SAMPLING_SOLID_ANGLE, Area = RAYLAB_LIGHT_SAMPLING_AREA };
enum class Accel { Bvh = RAYLAB_ACCEL_BVH, Boxes = RAYLAB_ACCEL_BOXES, None = RAYLAB_ACCEL_NONE };

struct RenderSettings {
    int width = 640;             // pixels
    int height = 360;            // pixels
    int rpp = 1;                 // samples per pixel per pass (the thesis' rays-per-pixel knob)
    int spp = 64;                // target samples per pixel: the render stops when reached
    double timeBudget = 0.0;     // seconds; 0 = no limit. Stops at spp or time, whichever first
    int maxBounces = 8;          // scattering events per path; 0 = emission and sky only
    int rrDepth = 3;             // Russian roulette starts after this many bounces
    std::uint32_t seed = 1;      // sampler seed: same seed, same image bit for bit
    bool nee = true;             // next-event estimation: sample emissive spheres and the sky
    bool mis = true;             // with nee: weight light and BSDF samples by the power heuristic
    bool adaptive = true;        // samples per pixel block by its noise (render/adaptive_sampling.h)
    float exposure = 0.0f;       // EV stops: display value = linear × 2^exposure
    ToneMap toneMap = ToneMap::AcesFit;
    int showMipLevel = 0;        // 1: textured surfaces show their mip level as colours (debug)
    RenderStage stage = RenderStage::Full;   // teaching: build the renderer up stage by stage
    SamplerKind sampler = SamplerKind::Sobol;    // the best of bench/samplers.md
    DiffuseSampling diffuseSampling = DiffuseSampling::Cosine;   // bench/estimator_stages.md
    GgxSampling ggxSampling = GgxSampling::Vndf;
    LightSelection lightSelection = LightSelection::Power;
    LightSampling lightSampling = LightSampling::SolidAngle;   // bench/estimator_stages.md
    Accel accel = Accel::Bvh;
};

// render.adaptive takes effect with the samplers whose sequence runs past render.spp: stratified and
// zsobol lay out exactly render.spp samples per pixel, and an adaptive pixel takes more.
inline bool samplerTakesAdaptive(SamplerKind s) { return s == SamplerKind::Sobol || s == SamplerKind::Independent; }
inline bool adaptiveInEffect(const RenderSettings& r) { return r.adaptive && samplerTakesAdaptive(r.sampler); }

struct Material {
    std::string name;
    glm::vec3 albedo{0.8f};          // diffuse reflectance, each channel in [0, 1]
    float roughness = 1.0f;          // perceptual roughness r in [0, 1]; GGX alpha = r^2
    glm::vec3 f0{0.0f};              // specular reflectance at normal incidence; 0 = pure Lambert
    float transmission = 0.0f;       // fraction that is glass (dielectric of index ior; rough by roughness)
    float ior = 1.5f;                // index of refraction inside / outside, > 0
    glm::vec3 emission{0.0f};        // emitted radiance colour
    float emissionStrength = 0.0f;   // multiplies emission; radiance = emission × strength
    std::string albedoTexture;       // image file as written in the scene ("" = none); multiplies albedo
    int albedoTextureIndex = -1;     // into Scene::textures
    std::string normalTexture;       // tangent-space normal map ("" = none), read as linear data
    int normalTextureIndex = -1;     // into Scene::textures
    float normalScale = 1.0f;        // scales the normal map's x and y (glTF normalTexture.scale)
    float metallic = 0.0f;           // f0 = mix(f0, base colour, m), albedo = base colour × (1 − m)
    std::string roughnessTexture;    // multiplies roughness by its green channel (linear data)
    int roughnessTextureIndex = -1;
    std::string metallicTexture;     // multiplies metallic by its blue channel (linear data)
    int metallicTextureIndex = -1;
    std::string emissionTexture;     // multiplies the emitted radiance (sRGB-decoded colour)
    int emissionTextureIndex = -1;
    std::string specularTexture;     // multiplies f0 by its colour (sRGB-decoded like albedo_texture)
    int specularTextureIndex = -1;
    std::string occlusionTexture;    // baked ambient occlusion in red (linear data), shown by a debug view only
    int occlusionTextureIndex = -1;
    float occlusionStrength = 1.0f;  // [0, 1]: occlusion = 1 + strength × (texel − 1) (glTF occlusionTexture.strength)
    bool fromGltf = false;           // read from a mesh's glTF file, not the scene's "materials"
    bool doubleSided = true;         // glTF doubleSided: false emits from the front alone under emission_sides gltf
    glm::vec3 radiance() const { return emission * emissionStrength; }
};

// Placement of an object: world = translate · Rz · Ry · Rx · scale · local (scene/transform.h).
struct Transform {
    glm::vec3 translation{0.0f};   // world units
    glm::vec3 rotation{0.0f};      // degrees about x, then y, then z (extrinsic)
    glm::vec3 scale{1.0f};         // per axis, each > 0
    bool operator==(const Transform&) const = default;
};

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;   // world units, > 0
    int material = 0;      // index into Scene::materials
    Transform transform;   // scale must be uniform: a sphere stays a sphere
};

struct Mesh;

// A mesh tessellated and displaced on loading (src/mesh/displacement.h), so the BVH holds the true
// surface: each triangle split into 4^subdivision, each vertex moved along its normal by scale × the
// texture's red channel at its uv, the normals then recomputed.
struct MeshDisplacement {
    std::string texture;                  // image as written in the scene ("" = none), linear data
    float scale = 1.0f;                   // object-space units per unit of texture value
    int subdivision = 0;                  // levels of 1-to-4 triangle splits, [0, 8]
    std::shared_ptr<const Mesh> source;   // an inline mesh as written, before displacement (for the writer)
    std::size_t trianglesBefore = 0;      // triangles before subdivision
    double milliseconds = 0.0;            // time the subdivision and displacement took on loading
};

// Which faces of a mesh's emissive triangles emit (emission_sides): both, the front (the side the
// e01 × e02 normal faces) or, per triangle, what its glTF material's doubleSided says.
enum class EmissionSides { Both, Front, Gltf };

// A triangle mesh in its own (object) space, placed by `transform`. Normals and uvs are per
// vertex and either empty or as many as positions.
struct Mesh {
    std::string file;                    // OBJ path as written in the scene ("" = inline)
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // smooth shading when given
    std::vector<glm::vec2> uvs;
    std::vector<glm::uvec3> triangles;   // indices into positions (and normals, uvs)
    int material = 0;                    // index into Scene::materials
    // Per triangle (glTF materials): index into Scene::materials, -1 = `material`. Empty = all `material`.
    std::vector<int> triangleMaterials;
    Transform transform;
    EmissionSides emissionSides = EmissionSides::Both;
    MeshDisplacement displacement;
};

// A light without a surface (pbrt-v4 PointLight, SpotLight, DistantLight). Point and spot lights
// emit intensity I (W/sr) from `position`, given as `intensity` or as `power` (exactly one);
// render/light_list.h turns power into intensity.
struct Light {
    enum class Type { Point, Spot, Distant };
    Type type = Type::Point;
    glm::vec3 position{0.0f};           // point, spot: world units
    glm::vec3 direction{0.0f, -1.0f, 0.0f};   // spot: the cone's axis; distant: where the light travels (any length > 0)
    glm::vec3 intensity{1.0f};          // point, spot: W/sr (when power is 0)
    float power = 0.0f;                 // point, spot: W, > 0 replaces intensity (grey)
    float innerAngle = 25.0f;           // spot: full intensity inside, degrees from the axis
    float outerAngle = 30.0f;           // spot: nothing outside, degrees, in [inner, 90]
    glm::vec3 irradiance{1.0f};         // distant: W/m² on a surface facing it
    float angularRadius = 0.0f;         // distant: degrees, [0, 90); 0 = a delta light
};

// Radiance for rays that leave the scene.
struct Sky {
    enum class Type { Constant, Gradient, Map };
    Type type = Type::Gradient;
    std::filesystem::path map;               // Map: equirectangular HDR image (resolved path)
    float rotation = 0.0f;                   // Map: degrees about +y
    glm::vec3 color{1.0f};                   // Constant: the radiance
    glm::vec3 top{0.5f, 0.7f, 1.0f};         // Gradient: radiance straight up (+y)
    glm::vec3 bottom{1.0f, 1.0f, 1.0f};      // Gradient: radiance straight down (-y)
    float strength = 1.0f;                   // multiplies the above
};

// The ambient-occlusion debug view (shaders/include/debug_views.glsl): what it traces.
struct AmbientOcclusion {
    float distance = 1.0f;   // world units, > 0: a ray that travels this far unblocked is open
    int rays = 4;            // cosine-weighted rays per camera sample, [1, 64]
};

struct Scene {
    std::filesystem::path sourcePath;   // the file it came from (for messages and metadata)
    Camera camera;
    RenderSettings render;
    Sky sky;
    AmbientOcclusion ao;
    std::vector<Material> materials;
    std::vector<Sphere> spheres;
    std::vector<Mesh> meshes;
    std::vector<Light> lights;       // point, spot and distant lights (emitters are materials)
    std::vector<Texture> textures;   // loaded images, referenced by the materials' *TextureIndex
    std::vector<std::string> warnings;   // non-fatal notes from loading (glTF features ignored, ...)
};

} // namespace raylab
