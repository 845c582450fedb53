#include "renderer/bvh/mesh_triangles.h"

namespace glint::bvh {

MeshTriangles trianglesFromMesh(const Mesh& mesh, const std::function<std::uint32_t(MaterialId)>& materialIndex)
{
    MeshTriangles out;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const Primitive& primitive = mesh.primitives[p];
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        const auto vertexCount = static_cast<std::uint32_t>(primitive.positions.size());
        out.positions.insert(out.positions.end(), primitive.positions.begin(), primitive.positions.end());
        const std::uint32_t material = materialIndex(primitive.material);
        for (std::size_t t = 0; t < primitive.triangleCount(); ++t) {
            const glm::uvec3 local{primitive.indices[3 * t], primitive.indices[3 * t + 1], primitive.indices[3 * t + 2]};
            if (local.x >= vertexCount || local.y >= vertexCount || local.z >= vertexCount) continue;
            out.triangles.push_back(local + base);
            out.materials.push_back(material);
            out.primitiveOf.push_back(static_cast<std::uint32_t>(p));
        }
    }
    return out;
}

} // namespace glint::bvh
