#pragma once
// Ray tests against the analytic shapes in their local space (the same shapes the path tracer
// draws exactly), for click picking. The ray direction may have any length: t is in its units.
#include "renderer/bvh/aabb.h"
#include "renderer/bvh/ray.h"
#include "scene/core/components.h"

namespace glint::editor {

// On a hit with 0 < t < tMax, lowers tMax and returns true. The ground plane is not handled here
// (it is infinite and stays out of the BVH): see intersectGroundPlane.
bool intersectShape(const Shape& shape, const bvh::Ray& localRay, float& tMax);
bool intersectGroundPlane(const bvh::Ray& localRay, float& tMax);
// The local bounds of a bounded shape (empty for the ground plane).
bvh::Aabb shapeBounds(const Shape& shape);

} // namespace glint::editor
