#pragma once
// A tiny OBJ reader for the BVH tests and benchmark: positions and faces only (polygons fanned
// into triangles, v/vt/vn and negative indices accepted). Not the importer: that is Assimp's job.
#include "renderer/bvh/mesh_triangles.h"

#include <filesystem>

namespace glint::bvh::test {

// Throws std::runtime_error naming the file and line on anything it cannot read.
MeshTriangles readObjTriangles(const std::filesystem::path& file);

} // namespace glint::bvh::test
