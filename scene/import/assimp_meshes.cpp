#include "assimp_meshes.h"

#include <assimp/mesh.h>

#include <cmath>

namespace glint {

namespace {

glm::vec3 toGlm(const aiVector3D& v) { return {v.x, v.y, v.z}; }

bool isFinite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

glm::vec3 usableNormal(glm::vec3 n) {
    const float length = glm::length(n);
    return std::isfinite(length) && length > 1e-12f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

void copyAttributes(const aiMesh& mesh, Primitive& p) {
    const unsigned n = mesh.mNumVertices;
    p.positions.reserve(n);
    for (unsigned i = 0; i < n; ++i) p.positions.push_back(toGlm(mesh.mVertices[i]));
    if (mesh.HasNormals())
        for (unsigned i = 0; i < n; ++i) p.normals.push_back(usableNormal(toGlm(mesh.mNormals[i])));
    for (unsigned channel = 0; channel < 2; ++channel) {
        if (!mesh.HasTextureCoords(channel)) continue;
        auto& uv = channel == 0 ? p.uv0 : p.uv1;
        for (unsigned i = 0; i < n; ++i) uv.emplace_back(mesh.mTextureCoords[channel][i].x, mesh.mTextureCoords[channel][i].y);
    }
    if (mesh.HasVertexColors(0))
        for (unsigned i = 0; i < n; ++i) {
            const aiColor4D& c = mesh.mColors[0][i];
            p.colors.emplace_back(c.r, c.g, c.b, c.a);
        }
}

} // namespace

PrimitiveConversion convertPrimitive(const aiMesh& mesh, MaterialId material) {
    PrimitiveConversion out;
    out.primitive.material = material;
    copyAttributes(mesh, out.primitive);
    auto& indices = out.primitive.indices;
    indices.reserve(std::size_t(mesh.mNumFaces) * 3);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        // Assimp's validation step has checked every index against mNumVertices.
        if (face.mNumIndices != 3) {
            ++out.droppedFaces;
            continue;
        }
        const auto& positions = out.primitive.positions;
        if (!isFinite(positions[face.mIndices[0]]) || !isFinite(positions[face.mIndices[1]]) || !isFinite(positions[face.mIndices[2]])) {
            ++out.nonFiniteTriangles;
            continue;
        }
        indices.insert(indices.end(), face.mIndices, face.mIndices + 3);
    }
    return out;
}

} // namespace glint
