#pragma once
// One step of the binned-SAH build: measure a range of items, decide leaf or split, and partition
// the range in place. Pure function of the range's contents, so any thread may run it.
#include "renderer/bvh/aabb.h"
#include "renderer/bvh/bvh_build.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::bvh {

struct BuildItems {
    std::span<const Aabb> bounds;     // per item; non-finite boxes were replaced by empty ones
    std::vector<glm::vec3> centroids; // per item
    std::vector<std::uint32_t> order; // permuted in place, range by range
};

struct RangeSplit {
    Aabb bounds;              // of every item in the range
    bool leaf = true;
    std::uint32_t middle = 0; // split: [begin, middle) and [middle, end), both non-empty
};

RangeSplit splitRange(BuildItems& items, std::uint32_t begin, std::uint32_t end, const BuildOptions& options);

} // namespace glint::bvh
