#include "accel/scene_geometry.h"

#include "accel/escape_sides.h"

#include "scene/transform.h"

#include <chrono>

namespace raylab {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

glsl::GpuBvhNode gpuNode(const BvhNode& n, std::uint32_t nodeOffset, std::uint32_t primitiveOffset) {
    const bool leaf = n.count > 0;
    const Aabb b = n.bounds.empty() ? Aabb{glm::vec3(0.0f), glm::vec3(-1.0f)} : n.bounds;   // never hit
    return leaf ? glsl::bvhLeaf(b.min, b.max, primitiveOffset + n.index, n.count)
                : glsl::bvhInterior(b.min, b.max, nodeOffset + n.index, n.axis);
}

// Rows of the upper 3×4 part of an affine matrix (glm is column-major: m[column][row]).
void rows(const glm::mat4& m, glm::vec4& r0, glm::vec4& r1, glm::vec4& r2) {
    r0 = glm::vec4(m[0][0], m[1][0], m[2][0], m[3][0]);
    r1 = glm::vec4(m[0][1], m[1][1], m[2][1], m[3][1]);
    r2 = glm::vec4(m[0][2], m[1][2], m[2][2], m[3][2]);
}

} // namespace

SceneGeometry buildSceneGeometry(const Scene& scene, const BvhOptions& options) {
    SceneGeometry g;
    const auto start = Clock::now();
    double weightedSah = 0.0;
    for (const Mesh& mesh : scene.meshes) {
        std::vector<Aabb> bounds(mesh.triangles.size());
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
            for (int k = 0; k < 3; ++k) bounds[i].grow(mesh.positions[mesh.triangles[i][k]]);
        const Bvh bvh = buildBvh(bounds, options);
        const auto nodeOffset = std::uint32_t(g.meshNodes.size());
        const auto triangleOffset = std::uint32_t(g.triangles.size());
        const auto vertexOffset = std::uint32_t(g.vertices.size());
        for (const BvhNode& n : bvh.nodes) g.meshNodes.push_back(gpuNode(n, nodeOffset, triangleOffset));
        for (std::uint32_t t : bvh.order) {
            const int material = mesh.triangleMaterials.empty() ? -1 : mesh.triangleMaterials[t];
            const glm::uvec3 v = mesh.triangles[t];
            g.triangles.push_back({glm::vec4(mesh.positions[v.x], 0.0f), glm::vec4(mesh.positions[v.y], 0.0f),
                                   glm::vec4(mesh.positions[v.z], 0.0f),
                                   glm::uvec4(v + glm::uvec3(vertexOffset), unsigned(material + 1))});
        }
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::vec2 uv = mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[v];
            const glm::vec3 n = mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[v];
            g.vertices.push_back({glm::vec4(mesh.positions[v], uv.x), glm::vec4(n, uv.y)});
        }
        g.meshRoot.push_back(nodeOffset);
        g.meshBounds.push_back(bvh.nodes.empty() ? Aabb{} : bvh.nodes[0].bounds);
        g.meshTriangles.emplace_back(triangleOffset, std::uint32_t(mesh.triangles.size()));
        g.meshEscapeSides.push_back(meshEscapeSides(mesh));
        g.maxDepth = std::max(g.maxDepth, bvh.depth);
        weightedSah += bvh.sahCost() * double(mesh.triangles.size());
    }
    g.meshBuildSeconds = secondsSince(start);
    if (!g.triangles.empty()) g.meshSahCost = weightedSah / double(g.triangles.size());
    updateTopLevel(g, scene, options);
    return g;
}

Aabb transformedBounds(const Aabb& bounds, const glm::mat4& toWorld) {
    Aabb world;
    if (bounds.empty()) return world;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? bounds.max.x : bounds.min.x, (c & 2) ? bounds.max.y : bounds.min.y,
                               (c & 4) ? bounds.max.z : bounds.min.z);
        world.grow(glm::vec3(toWorld * glm::vec4(corner, 1.0f)));
    }
    return world;
}

void updateTopLevel(SceneGeometry& g, const Scene& scene, const BvhOptions& options) {
    const auto start = Clock::now();
    std::vector<glsl::GpuInstance> objects;
    std::vector<Aabb> bounds;
    g.spheres.clear();
    for (const Sphere& s : scene.spheres) {
        const Sphere w = worldSphere(s);
        glsl::GpuInstance inst{};
        const unsigned objectId = unsigned(g.spheres.size());   // spheres first (instanceObjectId)
        inst.info = glm::uvec4(glsl::INSTANCE_SPHERE, objectId, unsigned(s.material),
                               glsl::INSTANCE_ESCAPES_FRONT | (objectId << glsl::INSTANCE_OBJECT_ID_SHIFT));
        g.spheres.push_back({glm::vec4(w.center, w.radius), glm::uvec4(unsigned(s.material), 0u, 0u, 0u)});
        // Widened by a few ulps: the rounded c ± r may fall just inside the sphere's extent.
        const glm::vec3 slack = 4.0f * 5.9604645e-8f * (glm::abs(w.center) + glm::vec3(w.radius));
        bounds.push_back(Aabb{w.center - glm::vec3(w.radius) - slack, w.center + glm::vec3(w.radius) + slack});
        inst.worldMin = glm::vec4(bounds.back().min, 0.0f);
        inst.worldMax = glm::vec4(bounds.back().max, 0.0f);
        objects.push_back(inst);
    }
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const glm::mat4 toWorld = transformMatrix(mesh.transform);
        const glm::mat4 toObject = inverseTransformMatrix(mesh.transform);
        glsl::GpuInstance inst{};
        rows(toObject, inst.worldToObject0, inst.worldToObject1, inst.worldToObject2);
        rows(toWorld, inst.objectToWorld0, inst.objectToWorld1, inst.objectToWorld2);
        const unsigned flags = (mesh.normals.empty() ? 0u : glsl::INSTANCE_HAS_NORMALS) |
                               (mesh.uvs.empty() ? 0u : glsl::INSTANCE_HAS_UVS) | g.meshEscapeSides.at(m);
        const unsigned objectId = unsigned(scene.spheres.size() + m);   // then meshes
        inst.info = glm::uvec4(glsl::INSTANCE_MESH, g.meshRoot.at(m), unsigned(mesh.material),
                               flags | (objectId << glsl::INSTANCE_OBJECT_ID_SHIFT));
        Aabb world = transformedBounds(g.meshBounds.at(m), toWorld);
        if (!world.empty()) {
            // The rounded corners may sit a little inside the exact box: widen by a few ulps.
            const glm::vec3 slack = 4.0f * 5.9604645e-8f * (glm::abs(world.min) + glm::abs(world.max));
            world.min -= slack;
            world.max += slack;
        }
        bounds.push_back(world);
        // An empty mesh gets an inverted box, which no ray enters.
        const glm::uvec2 triangles = g.meshTriangles.at(m);
        inst.worldMin = glm::vec4(world.empty() ? glm::vec3(0.0f) : world.min, glm::uintBitsToFloat(triangles.x));
        inst.worldMax = glm::vec4(world.empty() ? glm::vec3(-1.0f) : world.max, glm::uintBitsToFloat(triangles.y));
        objects.push_back(inst);
    }
    const Bvh top = buildBvh(bounds, options);
    g.topNodes.clear();
    for (const BvhNode& n : top.nodes) g.topNodes.push_back(gpuNode(n, 0u, 0u));
    g.instances.clear();
    for (std::uint32_t i : top.order) g.instances.push_back(objects[i]);
    // Each sphere knows its instance, so the linear top level can loop over spheres directly.
    for (std::size_t i = 0; i < g.instances.size(); ++i) {
        const glsl::GpuInstance& inst = g.instances[i];
        if (inst.info.x == glsl::INSTANCE_SPHERE) g.spheres[inst.info.y].info.y = unsigned(i);
    }
    g.topSahCost = top.sahCost();
    g.maxDepth = std::max(g.maxDepth, top.depth);
    g.topBuildSeconds = secondsSince(start);
}

} // namespace raylab
