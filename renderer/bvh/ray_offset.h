#pragma once
// Origins for spawned rays that neither re-hit their own surface (acne) nor start behind a nearby
// one (leaks), at any coordinate magnitude: Wächter and Binder, "A Fast and Robust Method for
// Avoiding Self-Intersection", Ray Tracing Gems ch. 6. Twin of shaders/bvh/ray_offset.glsl.
#include <glm/glm.hpp>

namespace glint::bvh {

// `p`: the hit point; `n`: the geometric normal (unit) on the side the new ray leaves from.
glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n);

} // namespace glint::bvh
