#pragma once
// Binned-SAH BVH over boxes, shared by both levels. The result depends only on the input boxes and
// the options, never on `threads` or on the order in which worker threads finish.
#include "renderer/bvh/aabb.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::bvh {

struct BuildOptions {
    int bins = 32;
    std::uint32_t maxLeafSize = 4; // items per leaf; a range this small or smaller may stay a leaf
    float traversalCost = 1.0f;    // SAH cost of visiting an interior node, relative to one item test
    int threads = 1;               // worker threads (1: build on the calling thread)
};

// count == 0: interior node whose children are nodes `first` and `first + 1`.
// count > 0 : leaf over items itemOrder[first .. first + count).
struct BvhNode {
    Aabb bounds;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    bool leaf() const { return count != 0; }
    friend bool operator==(const BvhNode&, const BvhNode&) = default;
};

// Nodes in depth-first order of sibling pairs; node 0 is the root. Empty input: no nodes.
struct Bvh {
    std::vector<BvhNode> nodes;
    std::vector<std::uint32_t> itemOrder; // slot -> index of the input box
    friend bool operator==(const Bvh&, const Bvh&) = default;
};

Bvh buildBvh(std::span<const Aabb> itemBounds, const BuildOptions& options);

// Surface area heuristic cost of the whole tree: traversalCost * sum(SA interior) +
// sum(SA leaf * items), over SA(root). Comparable between builds of the same input.
double sahCost(const Bvh& bvh, float traversalCost = 1.0f);

// Depth of the deepest leaf (a lone root leaf has depth 1).
int maxDepth(const Bvh& bvh);

} // namespace glint::bvh
