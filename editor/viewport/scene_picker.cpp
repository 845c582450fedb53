#include "editor/viewport/scene_picker.h"

#include "editor/viewport/shape_intersect.h"
#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/mesh_bvh.h"
#include "renderer/bvh/top_level.h"
#include "renderer/bvh/traverse.h"
#include "renderer/gpu_scene/visibility.h"

#include <algorithm>
#include <utility>

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

// A lamp's radius as the renderer draws it (renderer/gpu_scene/packed_scene.cpp): in world metres,
// not scaled with its node; suns and delta lights have no sphere.
float lampRadius(const Light& light) { return light.type == LightType::Sun ? 0.0f : std::max(light.radius, 0.0f); }

} // namespace

ScenePicker::ScenePicker(const Scene& scene) {
    std::vector<bvh::MeshBvh> meshes;
    std::vector<MeshId> ids;
    std::map<MeshId, bool> seen;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        const auto* instance = node.get<MeshInstance>();
        if (!instance || !renderer::visibleInWorld(scene, node) || !scene.meshes.contains(instance->mesh)) continue;
        if (!seen.try_emplace(instance->mesh, true).second) continue;
        bvh::MeshBvh built = bvh::buildMeshBvh(bvh::trianglesFromMesh(scene.meshes.at(instance->mesh), [](MaterialId) { return 0u; }),
                                               bvh::BuildOptions{});
        if (built.triangles.triangleCount() == 0) continue;
        meshes.push_back(std::move(built));
        ids.push_back(instance->mesh);
    }
    std::vector<bvh::Aabb> bounds;
    for (const bvh::MeshBvh& mesh : meshes) bounds.push_back(mesh.bounds());
    adoptMeshes(std::move(bounds), ids, bvh::flattenScene(meshes, bvh::TopLevel{}));
    retarget(scene);
}

ScenePicker::ScenePicker(const Scene& scene, std::vector<bvh::Aabb> meshBounds, const std::vector<MeshId>& ids, bvh::FlatScene flat) {
    adoptMeshes(std::move(meshBounds), ids, std::move(flat));
    retarget(scene);
}

void ScenePicker::adoptMeshes(std::vector<bvh::Aabb> meshBounds, const std::vector<MeshId>& ids, bvh::FlatScene flat) {
    flat_ = std::move(flat);
    meshRoots_.resize(meshBounds.size());
    for (std::size_t i = 0; i < meshBounds.size(); ++i) {
        meshRoots_[i].bvh.nodes.resize(1);
        meshRoots_[i].bvh.nodes[0].bounds = meshBounds[i];
        meshIndex_[ids.at(i)] = static_cast<std::uint32_t>(i);
    }
}

void ScenePicker::retarget(const Scene& scene) {
    shapes_.clear();
    grounds_.clear();
    lamps_.clear();
    bounds_.clear();
    std::vector<bvh::Instance> instances;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        if (!renderer::visibleInWorld(scene, node)) continue;
        const glm::mat4 world = scene.worldFromNode(id);
        if (const auto* instance = node.get<MeshInstance>()) {
            const auto it = meshIndex_.find(instance->mesh);
            if (it == meshIndex_.end()) continue; // empty, or not in the mesh part
            instances.push_back({world, bvh::kInstanceMesh, it->second, id.value, {}});
            bounds_.emplace_back(id, transformBox(meshRoots_[it->second].bounds(), world));
        } else if (const auto* shape = node.get<Shape>()) {
            if (shape->kind == ShapeKind::GroundPlane) {
                grounds_.push_back({glm::inverse(world), id});
                continue;
            }
            instances.push_back({world, bvh::kInstanceShape, static_cast<std::uint32_t>(shapes_.size()), id.value, shapeBounds(*shape)});
            shapes_.push_back(*shape);
            bounds_.emplace_back(id, transformBox(shapeBounds(*shape), world));
        } else if (const auto* light = node.get<Light>(); light && lampRadius(*light) > 0.0f) {
            const glm::vec3 centre(world[3]);
            const float radius = lampRadius(*light);
            lamps_.push_back({centre, radius, id});
            bounds_.emplace_back(id, bvh::Aabb{centre - glm::vec3(radius), centre + glm::vec3(radius)});
        }
    }
    const bvh::TopLevel top = bvh::buildTopLevel(std::move(instances), meshRoots_);
    bvh::replaceTopLevel(flat_, bvh::flattenTopLevel(top, flat_.meshNodeCount));
}

PickResult ScenePicker::pick(const bvh::Ray& worldRay) const {
    PickResult result;
    float tMax = INFINITY;
    if (flat_.topLevel >= 0) {
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
    for (const Lamp& lamp : lamps_) {
        Shape sphere;
        sphere.kind = ShapeKind::Sphere;
        sphere.radius = lamp.radius;
        if (intersectShape(sphere, {worldRay.origin - lamp.centre, worldRay.direction}, tMax)) result.node = lamp.node;
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
