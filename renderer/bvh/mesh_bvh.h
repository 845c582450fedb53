#pragma once
// One mesh's bottom-level BVH. Built once per mesh; moving an instance never rebuilds it.
#include "renderer/bvh/bvh_build.h"
#include "renderer/bvh/mesh_triangles.h"

namespace glint::bvh {

struct MeshBvh {
    MeshTriangles triangles;
    Bvh bvh; // itemOrder: slot -> triangle index in `triangles`
    Aabb bounds() const { return bvh.nodes.empty() ? Aabb{} : bvh.nodes[0].bounds; }
};

// Leaves hold at most kMaxLeafTriangles (bvh_layout.h) whatever options.maxLeafSize says.
MeshBvh buildMeshBvh(MeshTriangles triangles, const BuildOptions& options);

} // namespace glint::bvh
