#pragma once
// CPU traversal of the flattened two-level BVH: the same buffers and the same steps as
// shaders/bvh/traverse.glsl. Used by the tests and by editor picking.
#include "renderer/bvh/flat_scene.h"
#include "renderer/bvh/ray.h"

#include <cstdint>
#include <functional>

namespace glint::bvh {

// Intersects shape instance `shape` with a ray in the shape's local space; on a hit closer than
// tMax it lowers tMax and returns true. Without one, shape instances are skipped.
using ShapeIntersector = std::function<bool(std::uint32_t shape, const Ray& localRay, float& tMax)>;

// The work of one walk, counted as the GPU's BVH heat map counts it (shaders/bvh/traverse.glsl,
// BVH_COUNT_COST): nodes taken off the stack and not culled (both levels), and primitive tests.
struct TraversalCost {
    int nodes = 0;
    int primitives = 0;
};

// Closest hit with 0 < t < tMax. `cost`, when given, is added to.
RayHit intersectClosest(const FlatScene& scene, const Ray& worldRay, float tMax,
                        const ShapeIntersector& shapes = nullptr, TraversalCost* cost = nullptr);

// Any hit with 0 < t < tMax (shadow rays). `cost`, when given, is added to.
bool occluded(const FlatScene& scene, const Ray& worldRay, float tMax, const ShapeIntersector& shapes = nullptr,
              TraversalCost* cost = nullptr);

} // namespace glint::bvh
