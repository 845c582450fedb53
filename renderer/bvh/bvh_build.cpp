#include "renderer/bvh/bvh_build.h"

#include "renderer/bvh/box_grid.h"
#include "renderer/bvh/huge_pages.h"
#include "renderer/bvh/parallel_for.h"
#include "renderer/bvh/sah_split.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace glint::bvh {
namespace {

// Ranges up to this many items are built start to finish by one task. A constant, not a function
// of the thread count: the set of tasks, and so the tree, is the same however many threads run them.
constexpr std::uint32_t kTaskItems = 4096;

// A range of the top phase (more than kTaskItems items), split level by level.
struct TopNode {
    BuildRange range;
    std::int32_t left = -1; // interior when >= 0: its children are `left` and `left + 1`
    std::int32_t task = -1; // a range of at most kTaskItems items: the task that builds it
};

// A node as a task writes it: BvhNode's layout (a subtree's root first, then sibling pairs depth
// first), interior links local to the subtree. Trivial, so the scratch array is never cleared.
struct RawNode {
    float lo[3];
    float hi[3];
    std::uint32_t first;
    std::uint32_t count;
};

// Non-finite boxes, and those beyond what a node grid can hold, become empty ones.
std::vector<BuildItem> buildItems(std::span<const Aabb> boxes)
{
    std::vector<BuildItem> items;
    items.reserve(boxes.size());
    adviseHugePages(items.data(), boxes.size() * sizeof(BuildItem));
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Aabb box = withinGridReach(boxes[i]) ? boxes[i] : Aabb{};
        items.push_back(BuildItem{box.lo, static_cast<std::uint32_t>(i), box.hi, 0u});
    }
    return items;
}

// Splits large ranges level by level; ranges on one level are independent, so they run in parallel.
// Returns the tree of large ranges; its small ranges are marked as tasks (in index order).
std::vector<TopNode> buildTopPhase(std::span<BuildItem> items, const BuildOptions& options, bool mayBeEmpty,
                                   std::vector<std::size_t>& tasks)
{
    std::vector<TopNode> top{TopNode{measureRange(items, 0, static_cast<std::uint32_t>(items.size()))}};
    std::vector<std::size_t> frontier{0};
    while (!frontier.empty()) {
        std::vector<std::size_t> large;
        for (std::size_t index : frontier) {
            if (top[index].range.count > kTaskItems) {
                large.push_back(index);
            } else {
                top[index].task = static_cast<std::int32_t>(tasks.size());
                tasks.push_back(index);
            }
        }
        std::vector<RangeSplit> splits(large.size());
        parallelFor(large.size(), options.threads, [&](std::size_t i) {
            SplitScratch scratch;
            splits[i] = splitRange(items, top[large[i]].range, options, mayBeEmpty, scratch);
        });
        frontier.clear();
        for (std::size_t i = 0; i < large.size(); ++i) {
            if (splits[i].leaf) continue;
            const auto left = static_cast<std::int32_t>(top.size());
            top[large[i]].left = left;
            top.push_back(TopNode{splits[i].left});
            top.push_back(TopNode{splits[i].right});
            frontier.push_back(static_cast<std::size_t>(left));
            frontier.push_back(static_cast<std::size_t>(left) + 1);
        }
    }
    return top;
}

RawNode rawNode(const Aabb& bounds, std::uint32_t first, std::uint32_t count)
{
    return RawNode{{bounds.lo.x, bounds.lo.y, bounds.lo.z}, {bounds.hi.x, bounds.hi.y, bounds.hi.z}, first, count};
}

// Builds one small range depth first into `out` (room for 2 * count - 1 nodes); returns the number
// of nodes written.
std::uint32_t buildSubtree(std::span<BuildItem> items, const BuildRange& range, const BuildOptions& options, bool mayBeEmpty,
                           RawNode* out)
{
    struct Pending {
        std::uint32_t node;
        BuildRange range;
    };
    std::vector<Pending> pending{Pending{0, range}};
    SplitScratch scratch;
    std::uint32_t size = 1;
    while (!pending.empty()) {
        const Pending next = pending.back();
        pending.pop_back();
        const RangeSplit split = splitRange(items, next.range, options, mayBeEmpty, scratch);
        if (split.leaf) {
            out[next.node] = rawNode(next.range.bounds, next.range.begin, next.range.count);
            continue;
        }
        const std::uint32_t children = size;
        size += 2;
        out[next.node] = rawNode(next.range.bounds, children, 0);
        pending.push_back(Pending{children + 1, split.right});
        pending.push_back(Pending{children, split.left});
    }
    return size;
}

// Where a task's subtree lands: its root at `root`, the rest from `block` on, in its own order.
struct Placement {
    std::size_t root = 0;
    std::size_t block = 0;
};

// Lays the top phase and the subtrees out as one array: depth first, sibling pairs adjacent, root
// at 0. A subtree's nodes after its root are contiguous in that order, so each is copied as a block.
std::vector<BvhNode> stitch(const std::vector<TopNode>& top, const std::vector<std::size_t>& tasks, const RawNode* scratch,
                            const std::vector<std::uint32_t>& sizes, int threads)
{
    std::vector<BvhNode> topNodes; // (index, node) of the top phase, written after the resize
    std::vector<std::size_t> topTargets;
    std::vector<Placement> placements(tasks.size());
    struct Ref {
        std::size_t node;
        std::size_t target;
    };
    std::vector<Ref> pending{Ref{0, 0}};
    std::size_t next = 1;
    while (!pending.empty()) {
        const Ref ref = pending.back();
        pending.pop_back();
        const TopNode& node = top[ref.node];
        if (node.task >= 0) {
            const auto task = static_cast<std::size_t>(node.task);
            placements[task] = Placement{ref.target, next};
            next += sizes[task] - 1;
        } else if (node.left < 0) {
            topNodes.push_back(BvhNode{node.range.bounds, node.range.begin, node.range.count});
            topTargets.push_back(ref.target);
        } else {
            topNodes.push_back(BvhNode{node.range.bounds, static_cast<std::uint32_t>(next), 0});
            topTargets.push_back(ref.target);
            const auto left = static_cast<std::size_t>(node.left);
            pending.push_back(Ref{left + 1, next + 1});
            pending.push_back(Ref{left, next});
            next += 2;
        }
    }
    std::vector<BvhNode> nodes;
    nodes.reserve(next);
    adviseHugePages(nodes.data(), next * sizeof(BvhNode));
    nodes.resize(next);
    for (std::size_t i = 0; i < topNodes.size(); ++i) nodes[topTargets[i]] = topNodes[i];
    parallelFor(tasks.size(), threads, [&](std::size_t task) {
        const RawNode* local = scratch + 2 * static_cast<std::size_t>(top[tasks[task]].range.begin);
        const Placement at = placements[task];
        for (std::size_t i = 0; i < sizes[task]; ++i) {
            const RawNode& raw = local[i];
            const std::uint32_t first = raw.count != 0 ? raw.first : static_cast<std::uint32_t>(at.block + raw.first - 1);
            nodes[i == 0 ? at.root : at.block + i - 1] =
                BvhNode{Aabb{{raw.lo[0], raw.lo[1], raw.lo[2]}, {raw.hi[0], raw.hi[1], raw.hi[2]}}, first, raw.count};
        }
    });
    return nodes;
}

} // namespace

Bvh buildBvh(std::span<const Aabb> itemBounds, const BuildOptions& options)
{
    Bvh bvh;
    if (itemBounds.empty()) return bvh;
    std::vector<BuildItem> items = buildItems(itemBounds);
    const bool mayBeEmpty = anyEmpty(items);
    std::vector<std::size_t> tasks;
    const std::vector<TopNode> top = buildTopPhase(items, options, mayBeEmpty, tasks);
    // Each task writes at twice its first item: a range of n items has at most 2n - 1 nodes, so
    // the tasks' areas never overlap.
    const auto scratch = std::make_unique_for_overwrite<RawNode[]>(2 * items.size());
    adviseHugePages(scratch.get(), 2 * items.size() * sizeof(RawNode));
    std::vector<std::uint32_t> sizes(tasks.size());
    parallelFor(tasks.size(), options.threads, [&](std::size_t t) {
        const BuildRange& range = top[tasks[t]].range;
        sizes[t] = buildSubtree(items, range, options, mayBeEmpty, scratch.get() + 2 * static_cast<std::size_t>(range.begin));
    });
    bvh.nodes = stitch(top, tasks, scratch.get(), sizes, options.threads);
    bvh.itemOrder.resize(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) bvh.itemOrder[i] = items[i].index;
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
