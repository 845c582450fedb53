#pragma once
// One step of the binned-SAH build: bin a range of items, decide leaf or split, and partition the
// range in place. Pure function of the range's contents, so any thread may run it.
//
// Items are records of box and index in one array that each partition permutes, so every pass over
// a range reads and writes it front to back (no indirection through an index array). A range
// carries its box and its centroids' box, computed by its parent's split (from the bins and during
// the partition), so a range is read twice per level: once to bin, once to partition.
#include "renderer/bvh/aabb.h"
#include "renderer/bvh/bvh_build.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::bvh {

// 32 bytes: lo, the item's index, hi. Two 16-byte halves, so a move is two vector moves.
struct BuildItem {
    glm::vec3 lo;
    std::uint32_t index;
    glm::vec3 hi;
    std::uint32_t unused;
};

struct BuildRange {
    std::uint32_t begin = 0;
    std::uint32_t count = 0;
    Aabb bounds;         // of the items' boxes
    Aabb centroidBounds; // of their centroids (an empty box's centroid is the origin)
};

struct RangeSplit {
    bool leaf = true;
    BuildRange left;  // split only: [begin, middle)
    BuildRange right; // split only: [middle, end); both non-empty
};

// A range's box and centroids' box, measured (the root, and the halves of a split that found no plane).
BuildRange measureRange(std::span<const BuildItem> items, std::uint32_t begin, std::uint32_t count);

// Whether any item's box is empty (lo above hi on an axis): their centroid is the origin, which
// splitRange then tests for. Without them it leaves the test out.
bool anyEmpty(std::span<const BuildItem> items);

// Working memory of splitRange that its caller keeps between calls (one per thread).
struct SplitScratch {
    std::vector<std::uint64_t> goesLeft; // the partition's side of each item, one bit each
    std::vector<std::uint32_t> binOf;    // each item's bins, one byte per axis
};

RangeSplit splitRange(std::span<BuildItem> items, const BuildRange& range, const BuildOptions& options, bool mayBeEmpty,
                      SplitScratch& scratch);

} // namespace glint::bvh
