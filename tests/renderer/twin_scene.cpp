#include "twin_scene.h"

#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/mesh_bvh.h"
#include "renderer/bvh/top_level.h"

#include <map>

namespace glint::test {

TwinScene twinScene(const Scene& scene) {
    std::vector<bvh::MeshBvh> meshes;
    std::map<MeshId, std::uint32_t> index;
    std::vector<bvh::Instance> instances;
    for (const NodeId id : scene.depthFirst()) {
        const auto* instance = scene.at(id).get<MeshInstance>();
        if (!instance) continue;
        auto [it, fresh] = index.try_emplace(instance->mesh, std::uint32_t(meshes.size()));
        if (fresh)
            meshes.push_back(bvh::buildMeshBvh(bvh::trianglesFromMesh(scene.meshes.at(instance->mesh), [](MaterialId) { return 0u; }),
                                               bvh::BuildOptions{}));
        instances.push_back({scene.worldFromNode(id), bvh::kInstanceMesh, it->second, id.value, {}});
    }
    TwinScene out;
    out.flat = bvh::flattenScene(meshes, bvh::buildTopLevel(std::move(instances), meshes));
    for (std::size_t i = 0; i < out.flat.instances.size() / bvh::kInstanceTexels; ++i) {
        const NodeId id{out.flat.instances[bvh::kInstanceTexels * i + 3].z};
        out.names.push_back(scene.at(id).name);
        out.worldFrom.push_back(scene.worldFromNode(id));
    }
    return out;
}

glm::vec3 hitNormal(const TwinScene& twin, const bvh::RayHit& hit) {
    const auto p = [&](std::size_t k) {
        return glm::vec3(twin.flat.trianglePositions[bvh::kTrianglePositionTexels * std::size_t(hit.slot) + k]);
    };
    const glm::vec3 local = glm::cross(p(1) - p(0), p(2) - p(0));
    const glm::mat4& worldFrom = twin.worldFrom[std::size_t(hit.instance)];
    return glm::normalize(glm::vec3(glm::transpose(glm::inverse(worldFrom)) * glm::vec4(local, 0.0f)));
}

} // namespace glint::test
