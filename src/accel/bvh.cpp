#include "accel/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace raylab {
namespace {

constexpr int kMaxBins = 64;

struct Builder {
    const std::vector<Aabb>& bounds;
    std::vector<glm::vec3> centers;
    const BvhOptions& options;
    Bvh& bvh;

    // Builds the node for order[begin, end) at nodes[index]'s place (appended depth first).
    void build(std::uint32_t begin, std::uint32_t end, int depth) {
        const std::uint32_t nodeIndex = std::uint32_t(bvh.nodes.size());
        bvh.nodes.emplace_back();
        bvh.depth = std::max(bvh.depth, depth);
        Aabb box, centroidBox;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.grow(bounds[bvh.order[i]]);
            centroidBox.grow(centers[bvh.order[i]]);
        }
        const std::uint32_t n = end - begin;
        auto makeLeaf = [&] {
            BvhNode& node = bvh.nodes[nodeIndex];
            node.bounds = box;
            node.index = begin;
            node.count = n;
        };
        const glm::vec3 extent = centroidBox.max - centroidBox.min;
        int axis = extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
        if (n <= 1 || !(extent[axis] > 0.0f)) {
            makeLeaf();   // one primitive, or all centroids coincide: nothing separates them
            return;
        }
        std::uint32_t mid = begin;
        if (depth >= options.medianSplitDepth) {
            mid = begin + n / 2;
            std::nth_element(bvh.order.begin() + begin, bvh.order.begin() + mid, bvh.order.begin() + end,
                             [&](std::uint32_t a, std::uint32_t b) { return centers[a][axis] < centers[b][axis]; });
        } else {
            // Binned SAH over all three axes.
            const int nb = std::clamp(options.bins, 2, kMaxBins);
            float bestCost = std::numeric_limits<float>::max();
            int bestAxis = -1, bestSplit = -1;
            std::array<Aabb, kMaxBins> binBox;
            std::array<std::uint32_t, kMaxBins> binCount;
            std::array<float, kMaxBins> rightArea{};
            std::array<std::uint32_t, kMaxBins> rightCount{};
            for (int a = 0; a < 3; ++a) {
                if (!(extent[a] > 0.0f) || !std::isfinite(float(nb) / extent[a])) continue;
                std::fill(binBox.begin(), binBox.end(), Aabb{});
                std::fill(binCount.begin(), binCount.end(), 0u);
                const float scale = float(nb) / extent[a];
                for (std::uint32_t i = begin; i < end; ++i) {
                    const std::uint32_t p = bvh.order[i];
                    const int b = std::min(nb - 1, int((centers[p][a] - centroidBox.min[a]) * scale));
                    binBox[std::size_t(b)].grow(bounds[p]);
                    ++binCount[std::size_t(b)];
                }
                // Sweep from the right, then from the left: cost of splitting after bin s.
                Aabb acc;
                std::uint32_t cnt = 0;
                for (int s = nb - 1; s > 0; --s) {
                    acc.grow(binBox[std::size_t(s)]);
                    cnt += binCount[std::size_t(s)];
                    rightArea[std::size_t(s)] = acc.surfaceArea();
                    rightCount[std::size_t(s)] = cnt;
                }
                acc = Aabb{};
                cnt = 0;
                for (int s = 0; s < nb - 1; ++s) {
                    acc.grow(binBox[std::size_t(s)]);
                    cnt += binCount[std::size_t(s)];
                    const std::uint32_t rc = rightCount[std::size_t(s + 1)];
                    if (cnt == 0 || rc == 0) continue;
                    const float cost = acc.surfaceArea() * float(cnt) + rightArea[std::size_t(s + 1)] * float(rc);
                    if (cost < bestCost) {
                        bestCost = cost;
                        bestAxis = a;
                        bestSplit = s;
                    }
                }
            }
            const float area = box.surfaceArea();
            const float splitCost = options.traversalCost + options.intersectionCost * bestCost / area;
            const float leafCost = options.intersectionCost * float(n);
            // The centroid extent is positive, so the extreme centroids land in the first and
            // last bins and some split is always valid. Above maxLeafSize a split is forced.
            if (bestAxis >= 0 && n <= std::uint32_t(options.maxLeafSize) && !(splitCost < leafCost)) {
                makeLeaf();
                return;
            }
            if (bestAxis < 0) {   // only denormal extents: fall back to the object median
                mid = begin + n / 2;
                std::nth_element(bvh.order.begin() + begin, bvh.order.begin() + mid, bvh.order.begin() + end,
                                 [&](std::uint32_t x, std::uint32_t y) { return centers[x][axis] < centers[y][axis]; });
            } else {
                axis = bestAxis;
                const float scale = float(nb) / extent[axis];
                const auto split = std::partition(bvh.order.begin() + begin, bvh.order.begin() + end,
                                                  [&](std::uint32_t p) {
                                                      const int b = std::min(nb - 1,
                                                          int((centers[p][axis] - centroidBox.min[axis]) * scale));
                                                      return b <= bestSplit;
                                                  });
                mid = std::uint32_t(split - bvh.order.begin());
            }
        }
        if (mid == begin || mid == end) {   // cannot happen with the checks above; stay safe
            mid = begin + n / 2;
        }
        build(begin, mid, depth + 1);
        const std::uint32_t second = std::uint32_t(bvh.nodes.size());
        build(mid, end, depth + 1);
        BvhNode& node = bvh.nodes[nodeIndex];
        node.bounds = box;
        node.index = second;
        node.count = 0;
        node.axis = std::uint32_t(axis);
    }
};

} // namespace

double Bvh::sahCost() const {
    if (nodes.empty()) return 0.0;
    const double root = nodes[0].bounds.surfaceArea();
    if (!(root > 0.0)) return double(nodes[0].count);
    double cost = 0.0;
    for (const BvhNode& n : nodes) {
        const double rel = n.bounds.surfaceArea() / root;
        cost += n.count == 0 ? rel : rel * double(n.count);
    }
    return cost;
}

Bvh buildBvh(const std::vector<Aabb>& primitiveBounds, const BvhOptions& options) {
    Bvh bvh;
    if (primitiveBounds.empty()) return bvh;
    bvh.order.resize(primitiveBounds.size());
    for (std::size_t i = 0; i < bvh.order.size(); ++i) bvh.order[i] = std::uint32_t(i);
    std::vector<glm::vec3> centers(primitiveBounds.size());
    for (std::size_t i = 0; i < centers.size(); ++i)
        centers[i] = primitiveBounds[i].empty() ? glm::vec3(0.0f) : primitiveBounds[i].center();
    bvh.nodes.reserve(2 * primitiveBounds.size());
    Builder builder{primitiveBounds, std::move(centers), options, bvh};
    builder.build(0, std::uint32_t(primitiveBounds.size()), 0);
    return bvh;
}

} // namespace raylab
