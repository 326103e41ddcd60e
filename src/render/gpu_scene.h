#pragma once
// The scene's data on the GPU: std430 buffers of geometry and materials, bound at the points
// shaders/include/scene_data.glsl declares. Positions are uploaded relative to an origin (the
// camera's position; render/camera_relative.h). Needs a current GL context.
#include "accel/scene_geometry.h"
#include "scene/scene.h"

#include <cstdint>

namespace raylab {

// Whether the material's metallic mix happens per hit on the GPU (a metallic texture, or metallic
// with an albedo texture); otherwise it is baked into the uploaded albedo and f0.
bool metallicOnGpu(const Material& m);

class GpuScene {
public:
    GpuScene();
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    void upload(const Scene& scene, const glm::dvec3& origin = glm::dvec3(0.0));
    // Objects moved (transforms, sphere centres) or a new origin: rebuilds only the top-level BVH,
    // and the meshes' few triangles where their transforms are baked (render/baked_mesh_transforms.h).
    void updateTransforms(const Scene& scene, const glm::dvec3& origin = glm::dvec3(0.0));
    // Materials' values edited (not which textures they use, nor how many there are): re-uploads
    // the material records and the light list; geometry, BVHs, textures and the sky stay.
    void updateMaterials(const Scene& scene, const glm::dvec3& origin = glm::dvec3(0.0));
    void bind() const;   // binds every buffer to its binding point

    int sphereCount() const { return sphereCount_; }
    int instanceCount() const { return int(relativeTop_.instances.size()); }   // spheres and meshes
    int lightCount() const { return lightCount_; }   // emissive spheres
    int triangleLightCount() const { return triangleLightCount_; }   // emissive triangles (with area)
    int analyticLightCount() const { return analyticLightCount_; }   // point, spot, distant lights that emit
    // Power of each light (spheres, triangles, then analytic; render/light_list.h), which picks them.
    const std::vector<double>& lightPower() const { return lightPower_; }
    float skyMapMax() const { return skyMapMax_; }    // largest channel of the sky map, 0 without
    float skyMapMeanWeight() const { return skyMapMeanWeight_; }   // of its sampling distribution
    // In world space, for the CPU (picking, statistics); the GPU's top level is camera-relative.
    const SceneGeometry& geometry() const { return geometry_; }
    // How often the meshes' BVHs were built (every upload) and the top level alone was rebuilt
    // (updateTransforms): what an edit cost, for the viewer's tests and counters.
    std::uint64_t meshBvhBuilds() const { return meshBvhBuilds_; }
    std::uint64_t topLevelUpdates() const { return topLevelUpdates_; }
    std::uint64_t materialUpdates() const { return materialUpdates_; }

private:
    void uploadSkyMap(const Sky& sky);
    void uploadMaterials(const Scene& scene);
    std::vector<glm::vec3> materialRadiance_;   // per material, for the light list

    unsigned sphereBuffer_ = 0;
    unsigned materialBuffer_ = 0;
    unsigned lightBuffer_ = 0;
    unsigned skyMapTexture_ = 0;
    float skyMapMax_ = 0.0f;
    float skyMapMeanWeight_ = 0.0f;
    unsigned envMarginalBuffer_ = 0;
    unsigned envConditionalBuffer_ = 0;
    int sphereCount_ = 0;
    int lightCount_ = 0;
    SceneGeometry geometry_;
    std::uint64_t meshBvhBuilds_ = 0;
    std::uint64_t topLevelUpdates_ = 0;
    std::uint64_t materialUpdates_ = 0;
    unsigned geometryBuffers_[5] = {};   // top nodes, mesh nodes, instances, triangles, vertices
    // Texture-buffer views of top nodes, mesh nodes, instances and triangles (scene_geometry.glsl).
    unsigned geometryTexels_[4] = {};
    void attachGeometryTexels(int view);
    unsigned textureTexels_ = 0;   // texture-buffer view of textureBuffers_[0] (scene_textures.glsl)
    unsigned materialTexels_ = 0;  // texture-buffer view of materialBuffer_ (scene_data.glsl materialAt)
    void uploadTopLevel(const Scene& scene, const glm::dvec3& origin);
    // Builds geometry_ and, where the meshes' transforms are baked (bakesMeshTransforms),
    // relativeMeshes_; uploads the GPU's mesh nodes and vertices (its triangles after the top level).
    void uploadMeshes(const Scene& scene, const glm::dvec3& origin);
    SceneGeometry& gpuMeshes();      // the meshes as the GPU holds them
    SceneGeometry relativeMeshes_;   // baked meshes relative to the origin (empty when not baked)
    SceneGeometry relativeTop_;   // spheres, instances and top nodes as uploaded (mesh data stays in geometry_)
    unsigned triangleLightBuffer_ = 0;   // emissive triangles
    unsigned lightAliasBuffer_ = 0;      // alias table over all lights, by power
    int triangleLightCount_ = 0;
    std::vector<double> lightPower_;
    unsigned triangleLightIndexBuffer_ = 0;   // per triangle 1 + its light index, 0 none
    unsigned lightTexels_[3] = {};   // texture-buffer views: triangle lights, alias table, light index (scene_data.glsl)
    unsigned analyticLightBuffer_ = 0;        // uniform block of point, spot and distant lights
    unsigned fewObjectsBuffer_ = 0;           // uniform block of the few-objects loops (render/few_objects.h)
    int analyticLightCount_ = 0;
    unsigned textureBuffers_[2] = {};    // texels, texture info
};

} // namespace raylab
