#pragma once
// One Assimp mesh -> one glint primitive (positions, normals, UV0/UV1, COLOR_0, triangle indices).
#include "scene/core/mesh.h"

struct aiMesh;

namespace glint {

struct PrimitiveConversion {
    Primitive primitive;
    std::size_t droppedFaces = 0; // points and lines: glTF triangles only
};

PrimitiveConversion convertPrimitive(const aiMesh& mesh, MaterialId material);

} // namespace glint
