#pragma once
// The scene's data on the GPU: std430 buffers of geometry and materials, bound at the points
// shaders/include/scene_data.glsl declares. Needs a current GL context.
#include "accel/scene_geometry.h"
#include "scene/scene.h"

namespace raylab {

class GpuScene {
public:
    GpuScene();
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    void upload(const Scene& scene);
    // Objects moved (transforms, sphere centres): rebuilds only the top-level BVH.
    void updateTransforms(const Scene& scene);
    void bind() const;   // binds every buffer to its binding point

    int sphereCount() const { return sphereCount_; }
    const SceneGeometry& geometry() const { return geometry_; }

private:
    unsigned sphereBuffer_ = 0;
    unsigned materialBuffer_ = 0;
    int sphereCount_ = 0;
    SceneGeometry geometry_;
    unsigned geometryBuffers_[5] = {};   // bindings 8–12: top nodes, mesh nodes, instances,
                                         // triangles, vertices
    void uploadTopLevel();
    unsigned textureBuffers_[2] = {};    // bindings 14–15: texels, texture info
};

} // namespace raylab
