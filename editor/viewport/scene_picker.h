#pragma once
// Click selection: a CPU ray pick through the same two-level BVH the path tracer uses
// (renderer/bvh), with the analytic shapes tested exactly. Built from a scene snapshot; rebuild
// it when geometry, structure, visibility or transforms change (the top level is cheap).
#include "renderer/bvh/flat_scene.h"
#include "renderer/bvh/ray.h"
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace glint::editor {

struct PickResult {
    NodeId node{};      // none: nothing hit
    float t = 0.0f;     // along the ray, in units of its direction
    glm::vec3 position{0.0f};
};

class ScenePicker {
public:
    explicit ScenePicker(const Scene& scene);
    PickResult pick(const bvh::Ray& worldRay) const;
    // World bounds of a node's own geometry (empty box when it has none): frame selection.
    bvh::Aabb worldBounds(NodeId node) const;
    std::vector<bvh::Aabb> instanceBounds() const; // every pickable node's world box

private:
    struct Ground {
        glm::mat4 localFromWorld;
        NodeId node;
    };
    bvh::FlatScene flat_;
    std::vector<Shape> shapes_;
    std::vector<Ground> grounds_;
    std::vector<std::pair<NodeId, bvh::Aabb>> bounds_;
};

} // namespace glint::editor
