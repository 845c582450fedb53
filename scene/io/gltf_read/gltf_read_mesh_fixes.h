#pragma once
// Turning what a glTF primitive may hold into Glint's indexed triangle lists, and repairs.
#include "scene/core/mesh.h"

#include <cstdint>
#include <vector>

namespace glint {

// glTF modes 4 (triangles), 5 (strip), 6 (fan) as a triangle list; strips alternate winding.
std::vector<std::uint32_t> triangleListFrom(int mode, const std::vector<std::uint32_t>& indices);

// Normals of zero length (or not finite) replaced by the area-weighted normal of the triangles that
// use the vertex ((0, 1, 0) if those are degenerate too). Returns how many were repaired.
std::size_t repairZeroNormals(Primitive& p);

} // namespace glint
