#pragma once
// Embree 3, the CPU's ray-rate anchor for `raylab-bench rays`: the scene's triangles in world
// space (one geometry per mesh) and its spheres as Embree sphere points, in one flat scene built
// with Embree's defaults. Optional: built only where CMake found Embree (RAYLAB_HAVE_EMBREE on
// this file alone); without it embreeAvailable() is false and constructing a peer throws.
#include "scene/scene.h"

#include "shaders/include/ray_cast.glsl"

#include <memory>
#include <string>
#include <vector>

namespace raylab {

bool embreeAvailable();
std::string embreeVersion();   // "3.13.5"; "" without Embree

class EmbreePeer {
public:
    explicit EmbreePeer(const Scene& scene);
    ~EmbreePeer();
    EmbreePeer(const EmbreePeer&) = delete;
    EmbreePeer& operator=(const EmbreePeer&) = delete;

    // Nearest hit of every ray with rtcIntersect1 (packets = 1) or rtcIntersect8 / 16 (8, 16:
    // consecutive rays as one packet), on `threads` std::threads; hits[i].instance is Embree's
    // geometry id (meshes in scene order, then one for all spheres).
    void cast(const std::vector<glsl::CastRay>& rays, std::vector<glsl::CastHit>& hits, int threads,
              int packets = 1) const;
    double buildSeconds() const { return buildSeconds_; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    double buildSeconds_ = 0.0;
};

} // namespace raylab
