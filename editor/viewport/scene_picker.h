#pragma once
// Click selection: a CPU ray pick through the same two-level BVH the path tracer uses
// (renderer/bvh), with the analytic shapes and the sphere lamps (point and spot lights with a
// radius) tested exactly.
//
// Two parts with different costs: the mesh part (mesh BVHs flattened, the expensive one) and the
// rest (top level over the instances, shapes, ground planes, lamps: cheap). The viewport gets the
// mesh part from the GPU scene's preparation on its worker thread (the mesh BVHs are built once,
// for both), and retarget()s the picker when only transforms, lights or time changed, which
// rebuilds the cheap part alone.
#include "renderer/bvh/flat_scene.h"
#include "renderer/bvh/ray.h"
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <map>
#include <vector>

namespace glint::editor {

struct PickResult {
    NodeId node{};      // none: nothing hit
    float t = 0.0f;     // along the ray, in units of its direction
    glm::vec3 position{0.0f};
};

class ScenePicker {
public:
    ScenePicker() = default; // picks nothing
    // Builds the mesh BVHs itself (on the calling thread).
    explicit ScenePicker(const Scene& scene);
    // Adopts mesh BVHs built elsewhere for `scene` (renderer::MeshData of a preparation):
    // `meshBounds[i]` is the root box of mesh BVH i, `ids[i]` its mesh, `flat` holds their flattened
    // nodes and triangles (its top level is replaced). Meshes of `scene` not in `ids` are skipped.
    ScenePicker(const Scene& scene, std::vector<bvh::Aabb> meshBounds, const std::vector<MeshId>& ids, bvh::FlatScene flat);

    // The same meshes with `scene`'s transforms, lights, shapes and cameras: valid while no mesh,
    // mesh instance, visibility or hierarchy changed since the mesh part was built.
    void retarget(const Scene& scene);

    PickResult pick(const bvh::Ray& worldRay) const;
    // World bounds of a node's own geometry (empty box when it has none): frame selection.
    bvh::Aabb worldBounds(NodeId node) const;
    std::vector<bvh::Aabb> instanceBounds() const; // every pickable node's world box
    const bvh::FlatScene& flat() const { return flat_; }

private:
    struct Ground {
        glm::mat4 localFromWorld;
        NodeId node;
    };
    struct Lamp {
        glm::vec3 centre;
        float radius;
        NodeId node;
    };
    void adoptMeshes(std::vector<bvh::Aabb> meshBounds, const std::vector<MeshId>& ids, bvh::FlatScene flat);

    bvh::FlatScene flat_; // mesh part, then the top level
    std::vector<bvh::MeshBvh> meshRoots_; // root boxes only: what the top level needs of each mesh
    std::map<MeshId, std::uint32_t> meshIndex_;
    std::vector<Shape> shapes_;
    std::vector<Ground> grounds_;
    std::vector<Lamp> lamps_;
    std::vector<std::pair<NodeId, bvh::Aabb>> bounds_;
};

} // namespace glint::editor
