#pragma once
// Both BVH levels flattened into the texel arrays of bvh_layout.h, ready for glTexBuffer uploads.
#include "renderer/bvh/mesh_bvh.h"
#include "renderer/bvh/top_level.h"

#include <glm/glm.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace glint::bvh {

struct FlatMeshRange {
    std::uint32_t rootNode = 0;      // absolute node index of this mesh's BVH root
    std::uint32_t nodeCount = 0;     // its nodes are rootNode .. rootNode + nodeCount - 1
    std::uint32_t firstSlot = 0;     // its first triangle slot
    std::uint32_t firstVertex = 0;   // its first vertex in the scene's vertex attribute arrays
    std::uint32_t triangleCount = 0;
    std::uint32_t vertexCount = 0;
};

// The top-level part, rewritten alone when transforms change.
struct FlatTopLevel {
    std::vector<glm::uvec4> nodeBounds; // appended to FlatScene::nodeBounds at topLevelRoot
    std::vector<glm::uvec4> nodeLinks; // appended to FlatScene::nodeLinks at topLevelRoot
    std::vector<glm::uvec4> instances; // the whole uBvhInstances buffer
};

struct FlatScene {
    std::vector<glm::uvec4> nodeBounds;       // uBvhNodeBounds
    std::vector<glm::uvec4> nodeLinks;        // uBvhNodeLinks
    std::vector<glm::vec4> trianglePositions; // uBvhTrianglePositions
    std::vector<glm::uvec4> triangleVertices; // uBvhTriangleVertices
    std::vector<glm::uvec4> instances;        // uBvhInstances
    std::int32_t topLevelRoot = -1;           // uBvhTopLevelRoot; -1: no instances
    std::uint32_t meshNodeCount = 0;          // nodes before the top level
    std::vector<FlatMeshRange> meshes;
    std::vector<std::uint32_t> slotTriangle;  // CPU only: slot -> triangle index within its mesh
    friend bool operator==(const FlatScene&, const FlatScene&) = default;
};

// Texel `texel` of the node bounds as floats: 2n is node n's min corner, 2n + 1 its max.
inline glm::vec3 nodeCorner(const FlatScene& scene, std::size_t texel)
{
    return std::bit_cast<glm::vec3>(glm::uvec3(scene.nodeBounds[texel]));
}

FlatScene flattenScene(const std::vector<MeshBvh>& meshes, const TopLevel& topLevel);

// The top level for a scene whose mesh part is already flattened (node indices start at
// `topLevelRoot`): after a transform change upload these three with glBufferSubData; the node
// buffers are only rewritten from `topLevelRoot` on.
FlatTopLevel flattenTopLevel(const TopLevel& topLevel, const std::vector<FlatMeshRange>& meshes,
                             std::uint32_t topLevelRoot);

// Replaces the top-level tail and the instances of `scene` (the CPU copy kept for picking).
void replaceTopLevel(FlatScene& scene, FlatTopLevel topLevel);

} // namespace glint::bvh
