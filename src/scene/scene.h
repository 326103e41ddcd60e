#pragma once
// The in-memory scene: what a scene file describes, after validation. Plain data; the loader
// (scene_loader.h) fills it, the renderer reads it. Units and ranges are in scenes/FORMAT.md.
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

// Pinhole camera (thin lens comes later). Right-handed, y up by default.
struct Camera {
    glm::vec3 position{0.0f, 1.0f, 6.0f}; // eye point, world units
    glm::vec3 lookAt{0.0f, 1.0f, 0.0f};   // point the view centre passes through
    glm::vec3 up{0.0f, 1.0f, 0.0f};       // approximate up; must not be parallel to the view axis
    float fovY = 40.0f;                   // vertical field of view, degrees, (0, 180)
};

// How the linear image is turned into display values for PNG (EXR stays linear).
enum class ToneMap { Clamp, Reinhard, AcesFit };

struct RenderSettings {
    int width = 640;             // pixels
    int height = 360;            // pixels
    int rpp = 1;                 // samples per pixel per pass (the thesis' rays-per-pixel knob)
    int spp = 64;                // target samples per pixel: the render stops when reached
    double timeBudget = 0.0;     // seconds; 0 = no limit. Stops at spp or time, whichever first
    int maxBounces = 8;          // scattering events per path; 0 = emission and sky only
    int rrDepth = 3;             // Russian roulette starts after this many bounces
    std::uint32_t seed = 1;      // sampler seed: same seed, same image bit for bit
    bool nee = false;            // next-event estimation: sample emissive spheres and the sky
    bool mis = true;             // with nee: weight light and BSDF samples by the power heuristic
    float exposure = 0.0f;       // EV stops: display value = linear × 2^exposure
    ToneMap toneMap = ToneMap::AcesFit;
};

struct Material {
    std::string name;
    glm::vec3 albedo{0.8f};          // diffuse reflectance, each channel in [0, 1]
    float roughness = 1.0f;          // perceptual roughness r in [0, 1]; GGX alpha = r^2
    glm::vec3 f0{0.0f};              // specular reflectance at normal incidence; 0 = pure Lambert
    float transmission = 0.0f;       // fraction that is smooth glass (dielectric of index ior)
    float ior = 1.5f;                // index of refraction inside / outside, > 0
    glm::vec3 emission{0.0f};        // emitted radiance colour
    float emissionStrength = 0.0f;   // multiplies emission; radiance = emission × strength
    glm::vec3 radiance() const { return emission * emissionStrength; }
};

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;   // world units, > 0
    int material = 0;      // index into Scene::materials
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

struct Scene {
    std::filesystem::path sourcePath;   // the file it came from (for messages and metadata)
    Camera camera;
    RenderSettings render;
    Sky sky;
    std::vector<Material> materials;
    std::vector<Sphere> spheres;
};

} // namespace raylab
