#include "editor/viewport/scene_picker.h"

#include "editor/viewport/shape_intersect.h"
#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/mesh_bvh.h"
#include "renderer/bvh/top_level.h"
#include "renderer/bvh/traverse.h"
#include "renderer/gpu_scene/visibility.h"

#include <algorithm>
#include <map>

namespace glint::editor {

namespace {

bvh::Aabb transformBox(const bvh::Aabb& box, const glm::mat4& m) {
    bvh::Aabb out;
    if (box.empty()) return out;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 p((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z);
        out.grow(glm::vec3(m * glm::vec4(p, 1.0f)));
    }
    return out;
}

} // namespace

ScenePicker::ScenePicker(const Scene& scene) {
    std::vector<bvh::MeshBvh> meshes;
    std::map<MeshId, std::uint32_t> meshIndex;
    std::vector<bvh::Instance> instances;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        if (!renderer::visibleInWorld(scene, node)) continue;
        const glm::mat4 world = scene.worldFromNode(id);
        if (const auto* instance = node.get<MeshInstance>(); instance && scene.meshes.contains(instance->mesh)) {
            auto [it, fresh] = meshIndex.try_emplace(instance->mesh, static_cast<std::uint32_t>(meshes.size()));
            if (fresh)
                meshes.push_back(bvh::buildMeshBvh(bvh::trianglesFromMesh(scene.meshes.at(instance->mesh), [](MaterialId) { return 0u; }),
                                                   bvh::BuildOptions{}));
            if (meshes[it->second].triangles.triangleCount() == 0) continue;
            instances.push_back({world, bvh::kInstanceMesh, it->second, id.value, {}});
            bounds_.emplace_back(id, transformBox(meshes[it->second].bounds(), world));
        } else if (const auto* shape = node.get<Shape>()) {
            if (shape->kind == ShapeKind::GroundPlane) {
                grounds_.push_back({glm::inverse(world), id});
                continue;
            }
            instances.push_back({world, bvh::kInstanceShape, static_cast<std::uint32_t>(shapes_.size()), id.value, shapeBounds(*shape)});
            shapes_.push_back(*shape);
            bounds_.emplace_back(id, transformBox(shapeBounds(*shape), world));
        }
    }
    if (!instances.empty()) flat_ = bvh::flattenScene(meshes, bvh::buildTopLevel(std::move(instances), meshes));
}

PickResult ScenePicker::pick(const bvh::Ray& worldRay) const {
    PickResult result;
    float tMax = INFINITY;
    if (flat_.topLevelRoot >= 0) {
        const auto shapes = [this](std::uint32_t shape, const bvh::Ray& local, float& t) { return intersectShape(shapes_.at(shape), local, t); };
        const bvh::RayHit hit = bvh::intersectClosest(flat_, worldRay, tMax, shapes);
        if (hit.hit()) {
            tMax = hit.t;
            result.node = NodeId{flat_.instances[bvh::kInstanceTexels * static_cast<std::size_t>(hit.instance) + 3].z};
        }
    }
    for (const Ground& ground : grounds_) {
        const bvh::Ray local{glm::vec3(ground.localFromWorld * glm::vec4(worldRay.origin, 1.0f)),
                             glm::vec3(ground.localFromWorld * glm::vec4(worldRay.direction, 0.0f))};
        if (intersectGroundPlane(local, tMax)) result.node = ground.node;
    }
    if (result.node.value != 0) {
        result.t = tMax;
        result.position = worldRay.origin + tMax * worldRay.direction;
    }
    return result;
}

bvh::Aabb ScenePicker::worldBounds(NodeId node) const {
    const auto it = std::find_if(bounds_.begin(), bounds_.end(), [&](const auto& entry) { return entry.first == node; });
    return it == bounds_.end() ? bvh::Aabb{} : it->second;
}

std::vector<bvh::Aabb> ScenePicker::instanceBounds() const {
    std::vector<bvh::Aabb> boxes;
    for (const auto& entry : bounds_) boxes.push_back(entry.second);
    return boxes;
}

} // namespace glint::editor
