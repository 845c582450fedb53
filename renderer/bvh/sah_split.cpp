#include "renderer/bvh/sah_split.h"

#include "renderer/bvh/simd4.h"

#include <algorithm>
#include <bit>
#include <array>
#include <cstddef>
#include <cstring>
#include <limits>

namespace glint::bvh {
namespace {

using simd::F4;

constexpr int kMaxBins = 64;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Every accumulation below is min(new, accumulated) / max(new, accumulated) in SSE's operand
// order, which is glm::min(accumulated, new) / glm::max(accumulated, new): the same bits as the
// Aabb::grow calls they replace, signed zeros included.

struct Box4 {
    F4 lo;
    F4 hi;
};

// The item's box with lane 3 zeroed (it holds the index), and its centroid (the origin when empty).
// Without empty items in the build (MayBeEmpty false) the test for them is left out.
struct ItemGeometry {
    F4 lo;
    F4 hi;
    F4 centroid;
};

template <bool MayBeEmpty>
ItemGeometry geometry(const BuildItem& item)
{
    const F4 lo = simd::xyz(simd::load(&item.lo.x));
    const F4 hi = simd::load(&item.hi.x); // lane 3: `unused`, zero
    const F4 centre = (lo + hi) * simd::splat(0.5f);
    if constexpr (!MayBeEmpty) return {lo, hi, centre};
    const bool empty = (simd::greaterMask(lo, hi) & 7) != 0;
    return {lo, hi, simd::zeroIf(empty, centre)};
}

// Per axis, per bin: the box of the items whose centroid falls in it (lanes 0-2) and their count.
// The count is kept as a float in lane 3 of `hi`, where binning an item adds 1 with the same
// instruction that leaves lanes 0-2 as they are (adding -0). Floats count exactly up to 2^24
// (kFloatCounts); a longer range counts again into `count`. Only the first `bins` entries are
// reset and used.
constexpr std::uint32_t kFloatCounts = std::uint32_t{1} << 24;
constexpr std::uint32_t kTwoSetsFrom = 64;

struct Bins {
    std::array<std::array<Box4, kMaxBins>, 3> box;
    std::array<std::array<std::uint32_t, kMaxBins>, 3> count; // ranges longer than kFloatCounts only
};

// bin = (centroid - lo) * scale, truncated, clamped to [0, bins - 1]; NaN lands in bin 0. Equal to
// `f > 0 ? min(int(f), bins - 1) : 0` wherever that is defined (and bins - 1 for f past int range).
struct BinMapping {
    F4 lo = simd::splat(0.0f);
    F4 scale = simd::splat(0.0f);
    F4 top = simd::splat(0.0f); // bins - 1
    // Each lane's bin coordinate, clamped to [0, bins - 1] but not yet truncated.
    F4 clamped(F4 centroid) const { return simd::min(simd::max((centroid - lo) * scale, simd::splat(0.0f)), top); }
    // Each lane's bin times sizeof(Box4): its byte offset in its axis' bins.
    void offsets(F4 centroid, std::uint32_t offset[4]) const
    {
        static_assert(sizeof(Box4) == 32);
        simd::truncateShifted<5>(clamped(centroid), offset);
    }
    // The same offsets, and the three bins as the low bytes of the result (x lowest).
    std::uint32_t offsetsAndBins(F4 centroid, std::uint32_t offset[4]) const
    {
        return simd::truncateShiftedAndBytes<5>(clamped(centroid), offset);
    }
};

struct SplitChoice {
    float cost = kInfinity;
    int axis = 0;
    int firstRightBin = 0;
};

// Sorts the range into the bins of all three axes, in one pass over the items, and notes each
// item's bins in `binOf` (byte a of binOf[i]: item i's bin on axis a), which the partition then
// reads instead of the items. From kTwoSetsFrom items on, even and odd items go to
// two sets of bins, merged after: runs of items in one bin then do not wait for each other's stores.
template <bool MayBeEmpty, int Sets>
void fillBins(std::span<const BuildItem> range, const BinMapping& mapping, int binCount, Bins* sets, std::uint32_t* binOf)
{
    const std::size_t size = range.size();
    const F4 countOne = simd::set(-0.0f, -0.0f, -0.0f, 1.0f);
    const auto add = [&](Bins& bins, std::size_t axis, std::uint32_t offset, const ItemGeometry& g) {
        Box4& box = *reinterpret_cast<Box4*>(reinterpret_cast<unsigned char*>(bins.box[axis].data()) + offset);
        box.lo = simd::min(g.lo, box.lo);
        box.hi = simd::max(g.hi, box.hi) + countOne; // g.hi's lane 3 is zero, the count is not negative
    };
    const auto bin = [&](Bins& bins, std::size_t i) {
        const ItemGeometry g = geometry<MayBeEmpty>(range[i]);
        std::uint32_t offset[4];
        binOf[i] = mapping.offsetsAndBins(g.centroid, offset);
        add(bins, 0, offset[0], g);
        add(bins, 1, offset[1], g);
        add(bins, 2, offset[2], g);
    };
    static_assert(kMaxBins <= 128, "bins are noted as bytes and compared as signed ones");
    std::size_t i = 0;
    if constexpr (Sets == 2) {
        for (; i + 1 < size; i += 2) {
            bin(sets[0], i);
            bin(sets[1], i + 1);
        }
        const F4 countLane = simd::equalMask(simd::seti(0, 0, 0, 1), simd::splati(1));
        for (std::size_t axis = 0; axis < 3; ++axis) {
            for (std::size_t b = 0; b < static_cast<std::size_t>(binCount); ++b) {
                Box4& box = sets[0].box[axis][b];
                const Box4& other = sets[1].box[axis][b];
                box.lo = simd::min(other.lo, box.lo);
                box.hi = simd::select(countLane, box.hi + other.hi, simd::max(other.hi, box.hi));
            }
        }
    }
    for (; i < size; ++i) bin(sets[0], i);
}

// The counts again as integers, for a range too long for float counts: a second pass.
template <bool MayBeEmpty>
void countBins(std::span<const BuildItem> range, const BinMapping& mapping, int binCount, Bins& bins)
{
    for (std::size_t axis = 0; axis < 3; ++axis) std::fill_n(bins.count[axis].begin(), binCount, 0u);
    for (const BuildItem& item : range) {
        std::uint32_t offset[4];
        mapping.offsets(geometry<MayBeEmpty>(item).centroid, offset);
        for (std::size_t axis = 0; axis < 3; ++axis) ++bins.count[axis][offset[axis] / sizeof(Box4)];
    }
}

// The surface area of three boxes at once, one per lane, given as columns (lane i: box i's
// lo.x in loX, ...): Aabb::surfaceArea's operations in its order, 0 for an empty box.
F4 surfaceAreas(F4 loX, F4 loY, F4 loZ, F4 hiX, F4 hiY, F4 hiZ)
{
    const F4 empty = simd::greaterMaskLanes(loX, hiX) | simd::greaterMaskLanes(loY, hiY) | simd::greaterMaskLanes(loZ, hiZ);
    const F4 ex = hiX - loX, ey = hiY - loY, ez = hiZ - loZ;
    return simd::andNot(empty, simd::splat(2.0f) * (ex * ey + ey * ez + ez * ex));
}

// The best bin boundary over the axes in use: the lowest SAH cost times the parent's area
// (divided once, by the caller), the first axis and then the first boundary among equal costs.
// The three axes' sweeps run side by side, one per lane, on the bins transposed to columns.
SplitChoice chooseSplit(const Bins& bins, const std::array<bool, 3>& useAxis, int binCount, std::uint32_t count)
{
    struct Columns {
        F4 loX, loY, loZ, hiX, hiY, hiZ;
        simd::I4 count;
    };
    std::array<Columns, kMaxBins> columns;
    for (std::size_t b = 0; b < static_cast<std::size_t>(binCount); ++b) {
        Columns& c = columns[b];
        F4 counts;
        simd::transpose3(bins.box[0][b].lo, bins.box[1][b].lo, bins.box[2][b].lo, c.loX, c.loY, c.loZ);
        simd::transpose3(bins.box[0][b].hi, bins.box[1][b].hi, bins.box[2][b].hi, c.hiX, c.hiY, c.hiZ, counts);
        c.count = count <= kFloatCounts ? simd::truncatei(counts)
                                        : simd::seti(static_cast<std::int32_t>(bins.count[0][b]), static_cast<std::int32_t>(bins.count[1][b]),
                                                     static_cast<std::int32_t>(bins.count[2][b]), 0);
    }
    const F4 inf = simd::splat(kInfinity), negInf = simd::splat(-kInfinity);
    std::array<F4, kMaxBins> rightCost;
    F4 loX = inf, loY = inf, loZ = inf, hiX = negInf, hiY = negInf, hiZ = negInf;
    simd::I4 rightCount = simd::splati(0);
    for (int b = binCount - 1; b > 0; --b) {
        const Columns& c = columns[static_cast<std::size_t>(b)];
        loX = simd::min(c.loX, loX), loY = simd::min(c.loY, loY), loZ = simd::min(c.loZ, loZ);
        hiX = simd::max(c.hiX, hiX), hiY = simd::max(c.hiY, hiY), hiZ = simd::max(c.hiZ, hiZ);
        rightCount = rightCount + c.count;
        rightCost[static_cast<std::size_t>(b)] = surfaceAreas(loX, loY, loZ, hiX, hiY, hiZ) * simd::toFloat(rightCount);
    }
    const F4 used = simd::equalMask(simd::seti(useAxis[0], useAxis[1], useAxis[2], 0), simd::splati(1));
    const simd::I4 all = simd::splati(static_cast<std::int32_t>(count)), none = simd::splati(0);
    F4 bestCost = inf;
    simd::I4 bestBin = simd::splati(0);
    loX = inf, loY = inf, loZ = inf, hiX = negInf, hiY = negInf, hiZ = negInf;
    simd::I4 leftCount = simd::splati(0);
    for (int b = 1; b < binCount; ++b) {
        const Columns& c = columns[static_cast<std::size_t>(b - 1)];
        loX = simd::min(c.loX, loX), loY = simd::min(c.loY, loY), loZ = simd::min(c.loZ, loZ);
        hiX = simd::max(c.hiX, hiX), hiY = simd::max(c.hiY, hiY), hiZ = simd::max(c.hiZ, hiZ);
        leftCount = leftCount + c.count;
        const F4 cost = surfaceAreas(loX, loY, loZ, hiX, hiY, hiZ) * simd::toFloat(leftCount) + rightCost[static_cast<std::size_t>(b)];
        const F4 better = simd::andNot(simd::equalMask(leftCount, none) | simd::equalMask(leftCount, all), used & simd::lessMask(cost, bestCost));
        bestCost = simd::select(better, cost, bestCost);
        bestBin = simd::select(better, simd::splati(b), bestBin);
    }
    SplitChoice best;
    for (int axis = 0; axis < 3; ++axis) {
        const float cost = simd::lane(bestCost, axis);
        if (cost < best.cost) best = SplitChoice{cost, axis, simd::lanei(bestBin, axis)};
    }
    return best;
}

Aabb toAabb(F4 lo, F4 hi)
{
    return Aabb{{simd::lane(lo, 0), simd::lane(lo, 1), simd::lane(lo, 2)}, {simd::lane(hi, 0), simd::lane(hi, 1), simd::lane(hi, 2)}};
}

// The union of bins [first, last) on one axis: exactly the box of the items in them.
Aabb binBounds(const Bins& bins, int axis, int first, int last)
{
    F4 lo = simd::splat(kInfinity), hi = simd::splat(-kInfinity);
    for (int b = first; b < last; ++b) {
        lo = simd::min(bins.box[static_cast<std::size_t>(axis)][static_cast<std::size_t>(b)].lo, lo);
        hi = simd::max(bins.box[static_cast<std::size_t>(axis)][static_cast<std::size_t>(b)].hi, hi);
    }
    return toAabb(lo, hi);
}

// Swaps the 32 bytes of two items as two 16-byte halves.
void swapItems(BuildItem& a, BuildItem& b)
{
    const F4 aLo = simd::load(&a.lo.x), aHi = simd::load(&a.hi.x);
    simd::store(&a.lo.x, simd::load(&b.lo.x));
    simd::store(&a.hi.x, simd::load(&b.hi.x));
    simd::store(&b.lo.x, aLo);
    simd::store(&b.hi.x, aHi);
}

// Items whose bin on `axis` (in `binOf`, as fillBins noted it) is below `firstRight` go first;
// returns how many. The order within each side is that of libstdc++'s std::partition, which swaps
// the first item from the front that goes right with the first from the back that goes left, and so
// on inwards: the k-th item going right among the first L (L items go left) trades places with the
// k-th item going left from the back. That is done here without a branch per item: one pass marks
// each item's side in a bit array, 16 bins at a time, then the pairs are found with bit scans and
// swapped, then one pass over each side measures its centroids.
template <bool MayBeEmpty>
std::uint32_t partition(std::span<BuildItem> range, const std::uint32_t* binOf, int axis, int firstRight, std::vector<std::uint64_t>& goesLeft,
                        Aabb& leftCentroids, Aabb& rightCentroids)
{
    const std::size_t n = range.size();
    const auto threshold = static_cast<std::uint8_t>(firstRight);
    std::size_t leftCount = 0;
    goesLeft.resize((n + 63) / 64);
    for (std::size_t w = 0; w < goesLeft.size(); ++w) {
        const std::size_t begin = 64 * w, end = std::min(n, begin + 64);
        std::uint64_t word = 0;
        if (end - begin == 64) {
            for (std::size_t q = 0; q < 4; ++q) word |= std::uint64_t{simd::bytesBelow16(binOf + begin + 16 * q, axis, threshold)} << (16 * q);
        } else {
            for (std::size_t i = begin; i < end; ++i) word |= std::uint64_t{((binOf[i] >> (8 * axis)) & 0xFF) < threshold} << (i % 64);
        }
        goesLeft[w] = word;
        leftCount += static_cast<std::size_t>(std::popcount(word));
    }
    // The next item going right from the front trades places with the next going left from the
    // back, until the two meet. Bits past n in the last word read as "right" from the front: they
    // lie behind every item going left, so the scan stops there.
    std::size_t frontWord = 0, backWord = goesLeft.size() - 1;
    std::uint64_t front = ~goesLeft[0];      // items going right, from the front
    std::uint64_t back = goesLeft[backWord]; // items going left, from the back (no bits past n)
    for (;;) {
        while (front == 0 && frontWord + 1 < goesLeft.size()) front = ~goesLeft[++frontWord];
        while (back == 0 && backWord > 0) back = goesLeft[--backWord];
        if (front == 0 || back == 0) break;
        const std::size_t a = 64 * frontWord + static_cast<std::size_t>(std::countr_zero(front));
        const std::size_t b = 64 * backWord + 63 - static_cast<std::size_t>(std::countl_zero(back));
        if (a >= b) break;
        front &= front - 1;
        back &= ~(std::uint64_t{1} << (b % 64));
        swapItems(range[a], range[b]);
    }
    const auto centroids = [&](std::span<const BuildItem> side) {
        F4 cLo = simd::splat(kInfinity), cHi = simd::splat(-kInfinity);
        for (const BuildItem& item : side) {
            const F4 c = geometry<MayBeEmpty>(item).centroid;
            cLo = simd::min(c, cLo);
            cHi = simd::max(c, cHi);
        }
        return toAabb(cLo, cHi);
    };
    leftCentroids = centroids(range.first(leftCount));
    rightCentroids = centroids(range.subspan(leftCount));
    return static_cast<std::uint32_t>(leftCount);
}

} // namespace

BuildRange measureRange(std::span<const BuildItem> items, std::uint32_t begin, std::uint32_t count)
{
    F4 lo = simd::splat(kInfinity), hi = simd::splat(-kInfinity);
    F4 centroidLo = simd::splat(kInfinity), centroidHi = simd::splat(-kInfinity);
    for (const BuildItem& item : items.subspan(begin, count)) {
        const ItemGeometry g = geometry<true>(item);
        lo = simd::min(g.lo, lo);
        hi = simd::max(g.hi, hi);
        centroidLo = simd::min(g.centroid, centroidLo);
        centroidHi = simd::max(g.centroid, centroidHi);
    }
    return BuildRange{begin, count, toAabb(lo, hi), toAabb(centroidLo, centroidHi)};
}

namespace {

glm::vec3 centroidOf(const BuildItem& item)
{
    const bool empty = item.lo.x > item.hi.x || item.lo.y > item.hi.y || item.lo.z > item.hi.z;
    return empty ? glm::vec3(0.0f) : (item.lo + item.hi) * 0.5f;
}

// Two items (half of all ranges the build splits): the general path's answer without bins. On
// the first axis where the centroids differ, one item lands in bin 0 and the other in the last
// bin, so every boundary between costs SA(a) * 1 + SA(b) * 1, the same on every such axis: the
// general sweep picks boundary 1 on the first of them. The partition then swaps the two when the
// first item is the one that maps to the last bin.
RangeSplit splitPair(std::span<BuildItem> items, const BuildRange& range, const BuildOptions& options)
{
    RangeSplit split;
    BuildItem& a = items[range.begin];
    BuildItem& b = items[range.begin + 1];
    int axis = 0;
    while (axis < 3 && !(range.centroidBounds.hi[axis] - range.centroidBounds.lo[axis] > 0.0f)) ++axis;
    float bestCost = kInfinity;
    if (axis < 3) {
        const float parentArea = std::max(range.bounds.surfaceArea(), std::numeric_limits<float>::min());
        bestCost = (Aabb{a.lo, a.hi}.surfaceArea() * 1.0f + Aabb{b.lo, b.hi}.surfaceArea() * 1.0f) / parentArea;
    }
    if (2 <= options.maxLeafSize && 2.0f <= options.traversalCost + bestCost) return split;
    split.leaf = false;
    if (axis < 3) {
        const int binCount = std::clamp(std::min(options.bins, 4), 2, kMaxBins);
        const float extent = range.centroidBounds.hi[axis] - range.centroidBounds.lo[axis];
        const float scale = static_cast<float>(binCount) / extent;
        if ((centroidOf(a)[axis] - range.centroidBounds.lo[axis]) * scale >= 1.0f) swapItems(a, b);
    }
    const glm::vec3 ca = centroidOf(a), cb = centroidOf(b);
    split.left = BuildRange{range.begin, 1, Aabb{a.lo, a.hi}, Aabb{ca, ca}};
    split.right = BuildRange{range.begin + 1, 1, Aabb{b.lo, b.hi}, Aabb{cb, cb}};
    return split;
}

template <bool MayBeEmpty>
RangeSplit split(std::span<BuildItem> items, const BuildRange& range, const BuildOptions& options, SplitScratch& scratch)
{
    RangeSplit split;
    const std::uint32_t count = range.count;

    // Small ranges need no more bins than items: the sweep over empty bins was most of their cost.
    const int binCount = std::clamp(std::min(options.bins, static_cast<int>(std::max(count, 4u))), 2, kMaxBins);
    const float parentArea = std::max(range.bounds.surfaceArea(), std::numeric_limits<float>::min());
    std::array<bool, 3> useAxis{};
    int axisCount = 0;
    float scale[3] = {0.0f, 0.0f, 0.0f};
    for (int axis = 0; axis < 3; ++axis) {
        const float extent = range.centroidBounds.hi[axis] - range.centroidBounds.lo[axis];
        if (!(extent > 0.0f)) continue;
        scale[axis] = static_cast<float>(binCount) / extent;
        useAxis[static_cast<std::size_t>(axis)] = true;
        ++axisCount;
    }
    const glm::vec3& centroidLo = range.centroidBounds.lo;
    const BinMapping mapping{simd::set(centroidLo.x, centroidLo.y, centroidLo.z, 0.0f), simd::set(scale[0], scale[1], scale[2], 0.0f),
                             simd::splat(static_cast<float>(binCount - 1))};
    Bins sets[2];
    Bins& bins = sets[0];
    const int setCount = count >= kTwoSetsFrom ? 2 : 1;
    const Box4 empty{simd::splat(kInfinity), simd::set(-kInfinity, -kInfinity, -kInfinity, 0.0f)};
    for (int set = 0; set < setCount; ++set) {
        for (std::size_t axis = 0; axis < 3; ++axis) { // unused axes too: their lanes are swept, then ignored
            std::fill_n(sets[set].box[axis].begin(), binCount, empty);
        }
    }
    const std::span<BuildItem> rangeItems = items.subspan(range.begin, count);
    // Every axis is binned: one without extent has scale 0, so all its items land in bin 0, and
    // chooseSplit ignores it.
    if (scratch.binOf.size() < count) scratch.binOf.resize(count);
    if (axisCount > 0 && setCount == 2) fillBins<MayBeEmpty, 2>(rangeItems, mapping, binCount, sets, scratch.binOf.data());
    if (axisCount > 0 && setCount == 1) fillBins<MayBeEmpty, 1>(rangeItems, mapping, binCount, sets, scratch.binOf.data());
    if (axisCount > 0 && count > kFloatCounts) countBins<MayBeEmpty>(rangeItems, mapping, binCount, bins);
    const SplitChoice best = axisCount > 0 ? chooseSplit(bins, useAxis, binCount, count) : SplitChoice{};
    const float bestCost = best.cost / parentArea;
    const float leafCost = static_cast<float>(count);
    const float splitCost = options.traversalCost + bestCost;
    if (count <= options.maxLeafSize && leafCost <= splitCost) return split;

    split.leaf = false;
    if (bestCost == kInfinity) {
        // Every centroid coincides: no plane separates them, so halve the range as it stands.
        split.left = measureRange(items, range.begin, count / 2);
        split.right = measureRange(items, range.begin + count / 2, count - count / 2);
        return split;
    }
    Aabb leftCentroids, rightCentroids;
    const std::uint32_t leftCount =
        partition<MayBeEmpty>(rangeItems, scratch.binOf.data(), best.axis, best.firstRightBin, scratch.goesLeft, leftCentroids, rightCentroids);
    split.left = BuildRange{range.begin, leftCount, binBounds(bins, best.axis, 0, best.firstRightBin), leftCentroids};
    split.right = BuildRange{range.begin + leftCount, count - leftCount, binBounds(bins, best.axis, best.firstRightBin, binCount),
                             rightCentroids};
    return split;
}

} // namespace

bool anyEmpty(std::span<const BuildItem> items)
{
    for (const BuildItem& item : items)
        if (item.lo.x > item.hi.x || item.lo.y > item.hi.y || item.lo.z > item.hi.z) return true;
    return false;
}

RangeSplit splitRange(std::span<BuildItem> items, const BuildRange& range, const BuildOptions& options, bool mayBeEmpty,
                      SplitScratch& scratch)
{
    if (range.count <= 1) return RangeSplit{};
    if (range.count == 2) return splitPair(items, range, options);
    return mayBeEmpty ? split<true>(items, range, options, scratch) : split<false>(items, range, options, scratch);
}

} // namespace glint::bvh
