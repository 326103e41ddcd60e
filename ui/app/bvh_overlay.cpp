#include "app/bvh_overlay.h"

#include "shaders/include/instance_transform.glsl"

namespace raylab::ui {
namespace {

void collect(const std::vector<glsl::GpuBvhNode>& nodes, std::uint32_t i, int level, int depth, std::vector<Box>& out) {
    const glsl::GpuBvhNode& n = nodes.at(i);
    const bool leaf = glsl::bvhNodeIsLeaf(n);
    if (level == depth || leaf) {
        const Box b{glm::vec3(n.boundsMin), glm::vec3(n.boundsMax)};
        if (b.lo.x <= b.hi.x) out.push_back(b);   // empty nodes are stored inverted
        return;
    }
    collect(nodes, i + 1, level + 1, depth, out);   // the first child follows its parent
    collect(nodes, glsl::bvhNodeLink(n), level + 1, depth, out);
}

} // namespace

std::vector<Box> bvhLevel(const std::vector<glsl::GpuBvhNode>& nodes, std::uint32_t root, int depth) {
    std::vector<Box> out;
    if (root < nodes.size()) collect(nodes, root, 0, std::max(depth, 0), out);
    return out;
}

std::vector<Segment> topLevelBvhSegments(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                                         int depth) {
    std::vector<Segment> out;
    if (geometry.instances.empty()) return out;
    for (const Box& b : bvhLevel(geometry.topNodes, 0, depth)) {
        const auto s = projectBox(scene, width, height, b);
        out.insert(out.end(), s.begin(), s.end());
    }
    return out;
}

std::vector<Segment> meshBvhSegments(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                                     int depth) {
    std::vector<Segment> out;
    for (const glsl::GpuInstance& inst : geometry.instances) {
        if (inst.info.x != glsl::INSTANCE_MESH) continue;
        for (const Box& b : bvhLevel(geometry.meshNodes, inst.info.y, depth)) {
            std::array<glm::vec3, 8> corners;
            for (int i = 0; i < 8; ++i)
                corners[std::size_t(i)] = glsl::transformPoint(
                    inst.objectToWorld0, inst.objectToWorld1, inst.objectToWorld2,
                    glm::vec3(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z));
            const auto s = projectCorners(scene, width, height, corners);
            out.insert(out.end(), s.begin(), s.end());
        }
    }
    return out;
}

} // namespace raylab::ui
