#include "renderer/bvh/top_level.h"

#include "renderer/bvh/box_grid.h"
#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/mesh_bvh.h"

#include <cmath>

namespace glint::bvh {
namespace {

bool hittable(const Aabb& box)
{
    return !box.empty() && withinGridReach(box);
}

Aabb localBounds(const Instance& instance, const std::vector<MeshBvh>& meshes)
{
    if (instance.kind != kInstanceMesh) return instance.localBounds;
    return instance.target < meshes.size() ? meshes[instance.target].bounds() : Aabb{};
}

} // namespace

TopLevel buildTopLevel(std::vector<Instance> instances, const std::vector<MeshBvh>& meshes)
{
    TopLevel top;
    for (Instance& instance : instances) {
        const Aabb world = transformed(localBounds(instance, meshes), instance.worldFromLocal);
        const float det = glm::determinant(instance.worldFromLocal);
        if (!hittable(world) || !std::isfinite(det) || det == 0.0f) continue;
        top.instances.push_back(instance);
        top.worldBounds.push_back(world);
    }
    BuildOptions options;
    options.maxLeafSize = 1;
    top.bvh = buildBvh(top.worldBounds, options);
    return top;
}

} // namespace glint::bvh
