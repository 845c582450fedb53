#pragma once
// One Assimp mesh -> one glint primitive (positions, normals, UV0/UV1, COLOR_0, triangle indices).
// Normals that are not unit-length numbers (Assimp gives NaN for degenerate faces) become (0, 1, 0),
// as geometry.h does for flat normals.
#include "scene/core/mesh.h"

struct aiMesh;

namespace glint {

struct PrimitiveConversion {
    Primitive primitive;
    std::size_t droppedFaces = 0;      // points and lines: glTF triangles only
    std::size_t nonFiniteTriangles = 0; // using a NaN or infinite position: dropped
};

PrimitiveConversion convertPrimitive(const aiMesh& mesh, MaterialId material);

} // namespace glint
