#include "renderer/bvh/sah_split.h"

#include <algorithm>
#include <array>
#include <limits>

namespace glint::bvh {
namespace {

constexpr int kMaxBins = 64;

struct Bin {
    Aabb bounds;
    std::uint32_t count = 0;
};

struct BinMapping {
    int axis = 0;
    float lo = 0.0f;
    float scale = 0.0f;
    int bins = 1;
    // NaN-safe: anything not above `lo` lands in bin 0.
    int operator()(const glm::vec3& centroid) const
    {
        const float f = (centroid[axis] - lo) * scale;
        return f > 0.0f ? std::min(static_cast<int>(f), bins - 1) : 0;
    }
};

struct SplitChoice {
    float cost = std::numeric_limits<float>::infinity();
    BinMapping mapping;
    int firstRightBin = 0;
};

void measure(const BuildItems& items, std::uint32_t begin, std::uint32_t end, Aabb& bounds, Aabb& centroidBounds)
{
    for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t item = items.order[i];
        bounds.grow(items.bounds[item]);
        centroidBounds.grow(items.centroids[item]);
    }
}

// Best split along one axis: SAH cost (relative to the parent's area) of each bin boundary.
void chooseOnAxis(const BuildItems& items, std::uint32_t begin, std::uint32_t end, const BinMapping& mapping,
                  float parentArea, SplitChoice& best)
{
    std::array<Bin, kMaxBins> bins{};
    for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t item = items.order[i];
        Bin& bin = bins[static_cast<std::size_t>(mapping(items.centroids[item]))];
        bin.bounds.grow(items.bounds[item]);
        ++bin.count;
    }
    std::array<float, kMaxBins> rightCost{};
    Aabb right;
    std::uint32_t rightCount = 0;
    for (int b = mapping.bins - 1; b > 0; --b) {
        right.grow(bins[b].bounds);
        rightCount += bins[b].count;
        rightCost[b] = right.surfaceArea() * static_cast<float>(rightCount);
    }
    Aabb left;
    std::uint32_t leftCount = 0;
    for (int b = 1; b < mapping.bins; ++b) {
        left.grow(bins[b - 1].bounds);
        leftCount += bins[b - 1].count;
        if (leftCount == 0 || leftCount == end - begin) continue;
        const float cost = (left.surfaceArea() * static_cast<float>(leftCount) + rightCost[b]) / parentArea;
        if (cost < best.cost) best = SplitChoice{cost, mapping, b};
    }
}

} // namespace

RangeSplit splitRange(BuildItems& items, std::uint32_t begin, std::uint32_t end, const BuildOptions& options)
{
    RangeSplit split;
    Aabb centroidBounds;
    measure(items, begin, end, split.bounds, centroidBounds);
    const std::uint32_t count = end - begin;
    if (count <= 1) return split;

    const int binCount = std::clamp(options.bins, 2, kMaxBins);
    const float parentArea = std::max(split.bounds.surfaceArea(), std::numeric_limits<float>::min());
    SplitChoice best;
    for (int axis = 0; axis < 3; ++axis) {
        const float extent = centroidBounds.hi[axis] - centroidBounds.lo[axis];
        if (!(extent > 0.0f)) continue;
        const BinMapping mapping{axis, centroidBounds.lo[axis], static_cast<float>(binCount) / extent, binCount};
        chooseOnAxis(items, begin, end, mapping, parentArea, best);
    }
    const float leafCost = static_cast<float>(count);
    const float splitCost = options.traversalCost + best.cost;
    if (count <= options.maxLeafSize && leafCost <= splitCost) return split;

    split.leaf = false;
    if (best.cost == std::numeric_limits<float>::infinity()) {
        // Every centroid coincides: no plane separates them, so halve the range as it stands.
        split.middle = begin + count / 2;
        return split;
    }
    const auto first = items.order.begin() + begin;
    const auto middle = std::partition(first, items.order.begin() + end, [&](std::uint32_t item) {
        return best.mapping(items.centroids[item]) < best.firstRightBin;
    });
    split.middle = static_cast<std::uint32_t>(middle - items.order.begin());
    return split;
}

} // namespace glint::bvh
