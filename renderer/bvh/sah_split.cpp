#include "renderer/bvh/sah_split.h"

#include <algorithm>
#include <array>
#include <limits>

namespace glint::bvh {
namespace {

constexpr int kMaxBins = 64;

// No member initialisers: a range resets only the bins it uses (kEmptyBin).
struct Bin {
    glm::vec3 lo;
    glm::vec3 hi;
    std::uint32_t count;
};

constexpr float kInfinity = std::numeric_limits<float>::infinity();
const Bin kEmptyBin{glm::vec3(kInfinity), glm::vec3(-kInfinity), 0};

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

using AxisBins = std::array<Bin, kMaxBins>; // only the first `bins` entries of a mapping are used

// Sorts the range into the bins of every axis that has extent, in one pass over the items.
void fillBins(const BuildItems& items, std::uint32_t begin, std::uint32_t end, const std::array<BinMapping, 3>& mappings,
              const std::array<bool, 3>& useAxis, std::array<AxisBins, 3>& bins)
{
    for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t item = items.order[i];
        const glm::vec3& centroid = items.centroids[item];
        const Aabb& box = items.bounds[item];
        for (int axis = 0; axis < 3; ++axis) {
            if (!useAxis[axis]) continue;
            Bin& bin = bins[axis][static_cast<std::size_t>(mappings[axis](centroid))];
            bin.lo = glm::min(bin.lo, box.lo);
            bin.hi = glm::max(bin.hi, box.hi);
            ++bin.count;
        }
    }
}

// Best bin boundary on one axis: SAH cost times the parent's area (divided once, by the caller).
void chooseOnAxis(const AxisBins& bins, const BinMapping& mapping, std::uint32_t count, SplitChoice& best)
{
    std::array<float, kMaxBins> rightCost{};
    Aabb right;
    std::uint32_t rightCount = 0;
    for (int b = mapping.bins - 1; b > 0; --b) {
        right.grow(Aabb{bins[b].lo, bins[b].hi});
        rightCount += bins[b].count;
        rightCost[b] = right.surfaceArea() * static_cast<float>(rightCount);
    }
    Aabb left;
    std::uint32_t leftCount = 0;
    for (int b = 1; b < mapping.bins; ++b) {
        left.grow(Aabb{bins[b - 1].lo, bins[b - 1].hi});
        leftCount += bins[b - 1].count;
        if (leftCount == 0 || leftCount == count) continue;
        const float cost = left.surfaceArea() * static_cast<float>(leftCount) + rightCost[b];
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

    // Small ranges need no more bins than items: the sweep over empty bins was most of their cost.
    const int binCount = std::clamp(std::min(options.bins, static_cast<int>(std::max(count, 4u))), 2, kMaxBins);
    const float parentArea = std::max(split.bounds.surfaceArea(), std::numeric_limits<float>::min());
    std::array<BinMapping, 3> mappings{};
    std::array<bool, 3> useAxis{};
    for (int axis = 0; axis < 3; ++axis) {
        const float extent = centroidBounds.hi[axis] - centroidBounds.lo[axis];
        useAxis[axis] = extent > 0.0f;
        mappings[axis] = BinMapping{axis, centroidBounds.lo[axis], useAxis[axis] ? static_cast<float>(binCount) / extent : 0.0f, binCount};
    }
    std::array<AxisBins, 3> bins;
    for (AxisBins& axisBins : bins) std::fill_n(axisBins.begin(), binCount, kEmptyBin);
    fillBins(items, begin, end, mappings, useAxis, bins);
    SplitChoice best;
    for (int axis = 0; axis < 3; ++axis)
        if (useAxis[axis]) chooseOnAxis(bins[axis], mappings[axis], count, best);
    best.cost /= parentArea;
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
