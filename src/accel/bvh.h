#pragma once
// A bounding volume hierarchy over boxes, built with the binned surface area heuristic
// (Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", RT 2007; pbrt-v4
// BVHAggregate::buildRecursive, 12 buckets) and stored flat in depth-first order: an interior
// node's first child follows it, the second child's index is stored. Used for both levels: the
// triangles of one mesh, and the objects of a scene (shaders/include/bvh_traversal.glsl).
#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace raylab {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};

    void grow(glm::vec3 p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool empty() const { return min.x > max.x; }
    glm::vec3 center() const { return 0.5f * (min + max); }
    float surfaceArea() const {
        if (empty()) return 0.0f;
        const glm::vec3 e = max - min;
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

struct BvhNode {
    Aabb bounds;
    std::uint32_t index = 0;   // leaf: first entry of Bvh::order; interior: second child's node
    std::uint32_t count = 0;   // primitives in a leaf; 0 for an interior node
    std::uint32_t axis = 0;    // split axis of an interior node
};

struct BvhOptions {
    int bins = 16;                  // SAH bins per axis (2..64)
    int maxLeafSize = 4;            // leaves never hold more (unless primitives are inseparable)
    float traversalCost = 1.0f;     // cost of visiting a node, relative to one primitive test
    float intersectionCost = 1.0f;
    int medianSplitDepth = 40;      // below this depth, split at the object median: the GPU
                                    // traversal stack (64) can never overflow
};

struct Bvh {
    std::vector<BvhNode> nodes;           // nodes[0] is the root (absent when there are no primitives)
    std::vector<std::uint32_t> order;     // primitive indices in leaf order
    int depth = 0;                        // longest root-to-leaf path, in edges
    // SAH cost of the tree with Ct = Ci = 1: Σ interior A(n)/A(root) + Σ leaves N·A(n)/A(root).
    double sahCost() const;
};

// Builds over the primitives' bounds (empty boxes are allowed; they are never hit).
Bvh buildBvh(const std::vector<Aabb>& primitiveBounds, const BvhOptions& options = {});

} // namespace raylab
