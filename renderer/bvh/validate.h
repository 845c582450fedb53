#pragma once
// Checks a flattened scene before upload, so a bad BVH fails on the CPU with a message instead of
// rendering garbage or looping on the GPU.
#include "renderer/bvh/flat_scene.h"

#include <optional>
#include <string>

namespace glint::bvh {

// nullopt when valid. Otherwise the first problem found: a link out of range or pointing backwards
// (a cycle), a child box not inside its parent's, a triangle slot referenced twice or never, a leaf
// too large, a level deeper than kStackSize, an instance with a bad kind or target, or buffer
// lengths that disagree with each other.
std::optional<std::string> validateFlatScene(const FlatScene& scene);
// The same for the top level and the instances alone, after replaceTopLevel on a scene whose mesh
// part was validated before (a transform edit: the mesh trees did not change).
std::optional<std::string> validateTopLevel(const FlatScene& scene);

} // namespace glint::bvh
