#pragma once
// Every buffer of a FlatScene must fit the driver's GL_MAX_TEXTURE_BUFFER_SIZE (in texels).
#include "renderer/bvh/flat_scene.h"

#include <cstdint>
#include <optional>
#include <string>

namespace glint::bvh {

// nullopt when everything fits; otherwise a message naming the first buffer that does not, its
// size and the limit, e.g. "BVH buffer uBvhTrianglePositions needs 3000000 texels but
// GL_MAX_TEXTURE_BUFFER_SIZE is 65536 (1000000 triangles)".
std::optional<std::string> checkTextureBufferSizes(const FlatScene& scene, std::int64_t maxTexels);

} // namespace glint::bvh
