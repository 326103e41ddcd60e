#pragma once
// `raylab-bench rays`: nearest-hit rays per second through raylab's BVH on the GPU, against
// Embree 3 on the CPU (bench/embree_peer.h) and the CPU run of raylab's own traversal, for the
// same arrays of camera and bounce rays. Ray sets are made on the CPU, deterministic per seed.
#include "accel/scene_geometry.h"
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "scene/scene.h"

#include "shaders/include/ray_cast.glsl"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

using glsl::CastHit;
using glsl::CastRay;

struct RaySet {
    std::string name;            // "camera", "bounce"
    std::vector<CastRay> rays;
    int gridWidth = 1;           // rays per row when drawn as fragments
};

// One ray per pixel of a width × height image from the scene's camera (pinhole: the lens is
// ignored), through the pixel centre jittered within the pixel; row-major, top row first.
RaySet cameraRays(const Scene& scene, int width, int height, std::uint32_t seed);

// From each camera ray's first hit (found by the CPU traversal), a cosine-distributed direction
// about the geometric normal on the side the ray came from, the origin offset off the surface as
// the path tracer does (ray.glsl offsetRayOrigin). Missed camera rays make none.
RaySet bounceRays(const SceneGeometry& geometry, const RaySet& camera, std::uint32_t seed);

// The shader's traversal run on the CPU (accel/cpu_traversal.h), one thread.
std::vector<CastHit> castOnCpu(const SceneGeometry& geometry, const RaySet& set);

// The scene uploaded as the path tracer uploads it and entry/ray_cast.frag compiled for its
// features. Needs a current GL context.
class GpuRayCaster {
public:
    explicit GpuRayCaster(const Scene& scene);
    ~GpuRayCaster();
    GpuRayCaster(const GpuRayCaster&) = delete;
    GpuRayCaster& operator=(const GpuRayCaster&) = delete;

    void setRays(const RaySet& set);   // uploads the rays; not timed
    double cast();                     // traces them all once; wall seconds from glFinish to glFinish
    std::vector<CastHit> hits() const;
    const SceneGeometry& geometry() const { return scene_.geometry(); }
    double compileSeconds() const { return program_.compileSeconds(); }

private:
    GpuScene scene_;
    ShaderProgram program_;
    unsigned buffers_[2] = {};   // rays, hits
    unsigned framebuffer_ = 0;
    unsigned vertexArray_ = 0;
    int rayCount_ = 0;
    int gridWidth_ = 1;
};

// Two tracers' hits of the same rays compared ray by ray: they agree where both miss, or both hit
// at distances within tTolerance of each other, relative to the larger of t and the origin's
// distance from the world origin (a hit's t is known only to the rounding of the coordinates,
// pbrt-v4 §6.8, so a short ray far from the origin carries a large relative error).
struct Agreement {
    std::size_t rays = 0;
    std::size_t hitMiss = 0;     // one hits, the other misses
    std::size_t distance = 0;    // both hit, t differs beyond the tolerance
    double fraction() const { return rays ? 1.0 - double(hitMiss + distance) / double(rays) : 1.0; }
};
Agreement compareHits(const std::vector<CastRay>& rays, const std::vector<CastHit>& a, const std::vector<CastHit>& b,
                      float tTolerance = 1e-4f);

struct RayRateOptions {
    std::vector<std::filesystem::path> scenes;   // empty: Cornell box, the suite's large mesh, 10^6 triangles
    int rays = 1 << 18;      // camera rays per scene (image of the camera's aspect, about this many pixels)
    int repeat = 5;          // timed runs per tracer; the median is reported
    std::uint32_t seed = 1;
    std::filesystem::path out;   // Markdown file ('' = stdout only); text above its marker line is kept
    std::filesystem::path meshDir;   // where the 10^6-triangle mesh is generated when absent
    std::filesystem::path meshgen;   // the raylab-meshgen program that generates it
    std::string commandLine;
    std::string glDescription;
};

// Text of a results file above this line is kept when the bench rewrites it.
inline constexpr const char* kRayRateMarker = "<!-- raylab-bench rays writes everything below this line -->";

// Runs every scene, prints the table and writes it to options.out. Needs a current GL context.
int runRayRate(const RayRateOptions& options);

} // namespace raylab
