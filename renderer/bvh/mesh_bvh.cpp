#include "renderer/bvh/mesh_bvh.h"

#include "renderer/bvh/bvh_layout.h"

#include <algorithm>

namespace glint::bvh {

MeshBvh buildMeshBvh(MeshTriangles triangles, const BuildOptions& options)
{
    std::vector<Aabb> bounds(triangles.triangleCount());
    for (std::size_t t = 0; t < bounds.size(); ++t) {
        const glm::uvec3 tri = triangles.triangles[t];
        bounds[t].grow(triangles.positions[tri.x]);
        bounds[t].grow(triangles.positions[tri.y]);
        bounds[t].grow(triangles.positions[tri.z]);
    }
    BuildOptions meshOptions = options;
    meshOptions.maxLeafSize = std::clamp(options.maxLeafSize, 1u, kMaxLeafTriangles);
    MeshBvh mesh{std::move(triangles), {}};
    mesh.bvh = buildBvh(bounds, meshOptions);
    return mesh;
}

} // namespace glint::bvh
