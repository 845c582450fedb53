#include "renderer/bvh/bvh_build.h"

#include "renderer/bvh/parallel_for.h"
#include "renderer/bvh/sah_split.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace glint::bvh {
namespace {

// Ranges up to this many items are built start to finish by one task. A constant, not a function
// of the thread count: the set of tasks, and so the tree, is the same however many threads run them.
constexpr std::uint32_t kTaskItems = 4096;

// Children of an interior node are always allocated as a pair: `left` and `left + 1`.
struct TempNode {
    Aabb bounds;
    std::uint32_t begin = 0;
    std::uint32_t count = 0;
    std::int32_t left = -1; // interior when >= 0
    std::int32_t task = -1; // top-phase nodes only: the task that builds this subtree
};

using TempTree = std::vector<TempNode>;

bool finite(const Aabb& box)
{
    return std::isfinite(box.lo.x) && std::isfinite(box.lo.y) && std::isfinite(box.lo.z) &&
           std::isfinite(box.hi.x) && std::isfinite(box.hi.y) && std::isfinite(box.hi.z);
}

std::vector<Aabb> sanitised(std::span<const Aabb> boxes)
{
    std::vector<Aabb> out(boxes.begin(), boxes.end());
    for (Aabb& box : out)
        if (!finite(box)) box = Aabb{};
    return out;
}

void splitInto(TempTree& tree, std::size_t index, const RangeSplit& split)
{
    tree[index].bounds = split.bounds;
    if (split.leaf) return;
    const TempNode parent = tree[index];
    tree[index].left = static_cast<std::int32_t>(tree.size());
    tree.push_back(TempNode{{}, parent.begin, split.middle - parent.begin});
    tree.push_back(TempNode{{}, split.middle, parent.begin + parent.count - split.middle});
}

// Splits large ranges level by level; ranges on one level are independent, so they run in parallel.
// Returns the tree of large ranges; its small ranges are marked as tasks (in index order).
TempTree buildTopPhase(BuildItems& items, const BuildOptions& options, std::vector<std::size_t>& tasks)
{
    TempTree top{TempNode{{}, 0, static_cast<std::uint32_t>(items.order.size())}};
    std::vector<std::size_t> frontier{0};
    while (!frontier.empty()) {
        std::vector<std::size_t> large;
        for (std::size_t index : frontier) {
            if (top[index].count > kTaskItems) {
                large.push_back(index);
            } else {
                top[index].task = static_cast<std::int32_t>(tasks.size());
                tasks.push_back(index);
            }
        }
        std::vector<RangeSplit> splits(large.size());
        parallelFor(large.size(), options.threads, [&](std::size_t i) {
            const TempNode& node = top[large[i]];
            splits[i] = splitRange(items, node.begin, node.begin + node.count, options);
        });
        frontier.clear();
        for (std::size_t i = 0; i < large.size(); ++i) {
            splitInto(top, large[i], splits[i]);
            if (top[large[i]].left >= 0) {
                frontier.push_back(static_cast<std::size_t>(top[large[i]].left));
                frontier.push_back(static_cast<std::size_t>(top[large[i]].left) + 1);
            }
        }
    }
    return top;
}

TempTree buildSubtree(BuildItems& items, const TempNode& range, const BuildOptions& options)
{
    TempTree tree{TempNode{{}, range.begin, range.count}};
    std::vector<std::size_t> pending{0};
    while (!pending.empty()) {
        const std::size_t index = pending.back();
        pending.pop_back();
        const TempNode node = tree[index];
        splitInto(tree, index, splitRange(items, node.begin, node.begin + node.count, options));
        if (tree[index].left >= 0) {
            pending.push_back(static_cast<std::size_t>(tree[index].left) + 1);
            pending.push_back(static_cast<std::size_t>(tree[index].left));
        }
    }
    return tree;
}

// Lays both phases out as one array: depth first, sibling pairs adjacent, root at 0.
std::vector<BvhNode> stitch(const TempTree& top, const std::vector<TempTree>& subtrees)
{
    struct Ref {
        std::int32_t tree; // -1: the top phase
        std::size_t node;
        std::size_t target;
    };
    const auto resolve = [&](Ref ref) -> std::pair<const TempNode*, std::int32_t> {
        if (ref.tree < 0 && top[ref.node].task >= 0) return {&subtrees[static_cast<std::size_t>(top[ref.node].task)][0], top[ref.node].task};
        const TempTree& tree = ref.tree < 0 ? top : subtrees[static_cast<std::size_t>(ref.tree)];
        return {&tree[ref.node], ref.tree};
    };
    std::vector<BvhNode> nodes(1);
    std::vector<Ref> pending{Ref{-1, 0, 0}};
    while (!pending.empty()) {
        const Ref ref = pending.back();
        pending.pop_back();
        const auto [node, tree] = resolve(ref);
        if (node->left < 0) {
            nodes[ref.target] = BvhNode{node->bounds, node->begin, node->count};
            continue;
        }
        const std::size_t children = nodes.size();
        nodes.resize(children + 2);
        nodes[ref.target] = BvhNode{node->bounds, static_cast<std::uint32_t>(children), 0};
        const auto left = static_cast<std::size_t>(node->left);
        pending.push_back(Ref{tree, left + 1, children + 1});
        pending.push_back(Ref{tree, left, children});
    }
    return nodes;
}

} // namespace

Bvh buildBvh(std::span<const Aabb> itemBounds, const BuildOptions& options)
{
    Bvh bvh;
    if (itemBounds.empty()) return bvh;
    const std::vector<Aabb> boxes = sanitised(itemBounds);
    BuildItems items{boxes, std::vector<glm::vec3>(boxes.size()), std::vector<std::uint32_t>(boxes.size())};
    for (std::size_t i = 0; i < boxes.size(); ++i) items.centroids[i] = boxes[i].empty() ? glm::vec3(0.0f) : boxes[i].centre();
    std::iota(items.order.begin(), items.order.end(), 0u);

    std::vector<std::size_t> tasks;
    const TempTree top = buildTopPhase(items, options, tasks);
    std::vector<TempTree> subtrees(tasks.size());
    parallelFor(tasks.size(), options.threads,
                [&](std::size_t t) { subtrees[t] = buildSubtree(items, top[tasks[t]], options); });
    bvh.nodes = stitch(top, subtrees);
    bvh.itemOrder = std::move(items.order);
    return bvh;
}

double sahCost(const Bvh& bvh, float traversalCost)
{
    if (bvh.nodes.empty()) return 0.0;
    const double rootArea = bvh.nodes[0].bounds.surfaceArea();
    if (!(rootArea > 0.0)) return 0.0;
    double cost = 0.0;
    for (const BvhNode& node : bvh.nodes) {
        const double area = node.bounds.surfaceArea();
        cost += node.leaf() ? area * node.count : area * traversalCost;
    }
    return cost / rootArea;
}

int maxDepth(const Bvh& bvh)
{
    std::vector<int> depth(bvh.nodes.size(), 1);
    int deepest = bvh.nodes.empty() ? 0 : 1;
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        const BvhNode& node = bvh.nodes[i];
        if (node.leaf()) {
            deepest = std::max(deepest, depth[i]);
        } else {
            depth[node.first] = depth[i] + 1;
            depth[node.first + 1] = depth[i] + 1;
        }
    }
    return deepest;
}

} // namespace glint::bvh
