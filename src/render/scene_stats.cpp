#include "render/scene_stats.h"

#include "render/light_list.h"

#include <algorithm>
#include <cstdio>

namespace raylab {
SceneStats sceneStats(const Scene& scene, const SceneGeometry& geometry) {
    SceneStats s;
    s.spheres = scene.spheres.size();
    s.instances = scene.meshes.size();
    s.objects = s.spheres + s.instances;
    s.triangles = geometry.triangles.size();
    s.vertices = geometry.vertices.size();
    s.materials = scene.materials.size();
    s.topBvhNodes = geometry.topNodes.size();
    s.meshBvhNodes = geometry.meshNodes.size();
    s.bvhDepth = geometry.maxDepth;
    s.textures = scene.textures.size();
    // The layout render/gpu_scene.cpp uploads: every level's texels as vec4 (float RGBA) in one
    // buffer, and a table of uvec4: one header, one row per material, one per texture.
    std::size_t texels = 0;
    for (const Texture& t : scene.textures)
        for (const MipLevel& l : t.levels) texels += l.texels.size();
    if (!scene.textures.empty())
        s.textureBytes = texels * sizeof(glm::vec4) + (1 + scene.materials.size() + scene.textures.size()) * sizeof(glm::uvec4);
    // The light list next-event estimation picks from, so the counts are the tracer's: per-triangle
    // glTF materials count, zero-area triangles and textured emission do not.
    std::vector<glm::vec3> radiance;
    for (const Material& m : scene.materials) radiance.push_back(lightRadiance(m));
    const LightList lights = buildLightList(scene, geometry, radiance);
    s.emissiveSpheres = lights.spheres.size();
    s.emissiveTriangles = lights.triangles.size();
    s.analyticLights = lights.analytic.size();
    for (const Mesh& m : scene.meshes) {
        if (m.displacement.texture.empty()) continue;
        ++s.displacedMeshes;
        s.displacedTrianglesBefore += m.displacement.trianglesBefore;
        s.displacedTriangles += m.triangles.size();
        s.displacementMs += m.displacement.milliseconds;
    }
    return s;
}

std::string formatBytes(std::size_t bytes) {
    static const char* const units[] = {"B", "KiB", "MiB", "GiB"};
    double v = double(bytes);
    int u = 0;
    while (v >= 1024.0 && u < 3) {
        v /= 1024.0;
        ++u;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.1f %s", v, units[u]);
    return buf;
}

std::string describeDisplacement(const SceneStats& s) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "scene: displacement: %zu meshes, %zu -> %zu triangles, %.1f ms on loading",
                  s.displacedMeshes, s.displacedTrianglesBefore, s.displacedTriangles, s.displacementMs);
    return buf;
}

std::string describeSceneStats(const SceneStats& s) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "scene: %zu objects (%zu spheres, %zu mesh instances), %zu triangles, %zu materials\n"
                  "scene: BVH %zu top + %zu mesh nodes (depth %d); %zu textures, %s on the GPU; "
                  "lights: %zu emissive spheres, %zu emissive triangles, %zu point/spot/distant",
                  s.objects, s.spheres, s.instances, s.triangles, s.materials, s.topBvhNodes, s.meshBvhNodes,
                  s.bvhDepth, s.textures, formatBytes(s.textureBytes).c_str(), s.emissiveSpheres,
                  s.emissiveTriangles, s.analyticLights);
    std::string out = buf;
    if (s.displacedMeshes > 0) out += "\n" + describeDisplacement(s);
    return out;
}

} // namespace raylab
