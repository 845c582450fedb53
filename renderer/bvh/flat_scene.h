#pragma once
// Both BVH levels flattened into the texel arrays of bvh_layout.h, ready for glTexBuffer uploads.
#include "renderer/bvh/box_grid.h"
#include "renderer/bvh/bvh_layout.h"
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
    std::vector<glm::uvec4> nodes;     // appended to FlatScene::nodes at meshNodeCount
    std::vector<glm::uvec4> level;     // the top level's kLevelTexels, after the meshes' levels
    std::vector<glm::uvec4> instances; // the whole uBvhInstances buffer
};

struct FlatScene {
    std::vector<glm::uvec4> nodes;            // uBvhNodes
    std::vector<glm::uvec4> levels;           // uBvhLevels: each mesh's, then the top level's
    std::vector<glm::vec4> trianglePositions; // uBvhTrianglePositions
    std::vector<glm::uvec4> triangleVertices; // uBvhTriangleVertices
    std::vector<glm::uvec4> instances;        // uBvhInstances
    std::int32_t topLevel = -1;               // uBvhTopLevel (== meshes.size()); -1: no instances
    std::uint32_t meshNodeCount = 0;          // nodes before the top level
    std::vector<FlatMeshRange> meshes;
    std::vector<std::uint32_t> slotTriangle;  // CPU only: slot -> triangle index within its mesh
    friend bool operator==(const FlatScene&, const FlatScene&) = default;
};

// A packed link (bvh_layout.h) as (first, count), and back.
inline glm::uvec2 unpackLink(std::uint32_t link) { return {link >> 4u, link & 15u}; }
inline std::uint32_t packLink(glm::uvec2 link) { return (link.x << 4u) | link.y; }

// Node n's link as (first, count).
inline glm::uvec2 nodeLink(const FlatScene& scene, std::size_t node) { return unpackLink(scene.nodes[node].w); }

// Level l's grid, its root's link as (first, count), and its root's node index.
inline BoxGrid levelGrid(const FlatScene& scene, std::size_t level)
{
    return BoxGrid{std::bit_cast<glm::vec3>(glm::uvec3(scene.levels[kLevelTexels * level])),
                   std::bit_cast<glm::vec3>(glm::uvec3(scene.levels[kLevelTexels * level + 1]))};
}
inline glm::uvec2 levelRootLink(const FlatScene& scene, std::size_t level)
{
    return unpackLink(scene.levels[kLevelTexels * level].w);
}
inline std::uint32_t levelRootNode(const FlatScene& scene, std::size_t level) { return scene.levels[kLevelTexels * level + 1].w; }

// Node n's box as a walk tests it: its grid box on the level's grid.
inline Aabb nodeBox(const FlatScene& scene, const BoxGrid& grid, std::size_t node)
{
    return dequantize(grid, unpackGridBox(glm::uvec3(scene.nodes[node])));
}

FlatScene flattenScene(const std::vector<MeshBvh>& meshes, const TopLevel& topLevel);

// The top level for a scene whose mesh part is already flattened (node indices start at
// `firstNode`): after a transform change upload these three with glBufferSubData; the node
// buffer is only rewritten from `firstNode` on, the level buffer in its last kLevelTexels.
FlatTopLevel flattenTopLevel(const TopLevel& topLevel, std::uint32_t firstNode);

// Replaces the top-level tail and the instances of `scene` (the CPU copy kept for picking).
void replaceTopLevel(FlatScene& scene, FlatTopLevel topLevel);

} // namespace glint::bvh
