#include "mesh/subdivision.h"

#include <cstdint>
#include <unordered_map>

namespace raylab {
namespace {

Mesh splitOnce(const Mesh& in) {
    Mesh out = in;
    out.triangles.clear();
    out.triangles.reserve(4 * in.triangles.size());
    out.triangleMaterials.clear();
    std::unordered_map<std::uint64_t, unsigned> midpoints;
    midpoints.reserve(3 * in.triangles.size());
    auto midpoint = [&](unsigned a, unsigned b) {
        const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
        const auto [it, added] = midpoints.try_emplace(key, unsigned(out.positions.size()));
        if (!added) return it->second;
        out.positions.push_back(0.5f * (in.positions[a] + in.positions[b]));
        if (!in.normals.empty()) {
            const glm::vec3 n = in.normals[a] + in.normals[b];
            out.normals.push_back(glm::dot(n, n) > 0.0f ? glm::normalize(n) : in.normals[a]);
        }
        if (!in.uvs.empty()) out.uvs.push_back(0.5f * (in.uvs[a] + in.uvs[b]));
        return it->second;
    };
    for (std::size_t t = 0; t < in.triangles.size(); ++t) {
        const glm::uvec3 v = in.triangles[t];
        const unsigned ab = midpoint(v.x, v.y), bc = midpoint(v.y, v.z), ca = midpoint(v.z, v.x);
        // The children keep the parent's winding.
        out.triangles.insert(out.triangles.end(), {{v.x, ab, ca}, {ab, v.y, bc}, {ca, bc, v.z}, {ab, bc, ca}});
        if (!in.triangleMaterials.empty()) out.triangleMaterials.insert(out.triangleMaterials.end(), 4, in.triangleMaterials[t]);
    }
    return out;
}

} // namespace

Mesh subdivideMesh(const Mesh& mesh, int levels) {
    Mesh out = mesh;
    for (int l = 0; l < levels; ++l) out = splitOnce(out);
    return out;
}

} // namespace raylab
