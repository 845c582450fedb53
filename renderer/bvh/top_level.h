#pragma once
// The top level: a BVH over instances (meshes and bounded analytic shapes; the infinite ground
// plane stays outside and is tested on its own). Cheap to rebuild whenever a transform changes.
#include "renderer/bvh/bvh_build.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace glint::bvh {

struct Instance {
    glm::mat4 worldFromLocal{1.0f};
    std::uint32_t kind = 0;     // kInstanceMesh or kInstanceShape (bvh_layout.h)
    std::uint32_t target = 0;   // mesh: index into the mesh BVH list; shape: renderer's shape index
    std::uint32_t objectId = 0; // scene node id
    Aabb localBounds;           // shapes only; mesh instances use their mesh BVH's root box
};

struct TopLevel {
    // The instances there is something to hit in, in input order: those of empty meshes and those
    // with singular or non-finite transforms are left out.
    std::vector<Instance> instances;
    std::vector<Aabb> worldBounds; // per instance
    Bvh bvh;                       // leaves hold one instance each
};

struct MeshBvh;
// `meshes` gives mesh instances their local bounds (instance.target indexes it).
TopLevel buildTopLevel(std::vector<Instance> instances, const std::vector<MeshBvh>& meshes);

} // namespace glint::bvh
