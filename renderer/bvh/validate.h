#pragma once
// Checks a flattened scene before upload, so a bad BVH fails on the CPU with a message instead of
// rendering garbage or looping on the GPU.
#include "renderer/bvh/flat_scene.h"

#include <cstddef>
#include <optional>
#include <string>

namespace glint::bvh {

// nullopt when valid. Otherwise the first problem found: a link out of range or pointing backwards
// (a cycle), a child box not inside its parent's, a level whose grid is not power-of-two steps or
// whose texel disagrees with its root, a triangle slot referenced twice or never, a leaf too large,
// a level deeper than kStackSize, an instance with a bad kind or target, more nodes, slots or
// instances than a packed link addresses, or buffer lengths that disagree with each other.
std::optional<std::string> validateFlatScene(const FlatScene& scene);
// The same for the top level and the instances alone, after replaceTopLevel on a scene whose mesh
// part was validated before (a transform edit: the mesh trees did not change).
std::optional<std::string> validateTopLevel(const FlatScene& scene);
// Whether packed links (bvh_layout.h, kMaxLinkFirst) can address every node, slot and instance.
std::optional<std::string> checkLinkReach(std::size_t nodes, std::size_t slots, std::size_t instances);

} // namespace glint::bvh
