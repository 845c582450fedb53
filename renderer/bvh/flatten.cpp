#include "renderer/bvh/flat_scene.h"

#include "renderer/bvh/bvh_layout.h"

#include <bit>

namespace glint::bvh {
namespace {

// A node's box as float bits, with its link beside it (bvh_layout.h).
void appendBounds(std::vector<glm::uvec4>& out, const Aabb& box, glm::uvec2 link)
{
    out.emplace_back(std::bit_cast<glm::uvec3>(box.lo), link.x);
    out.emplace_back(std::bit_cast<glm::uvec3>(box.hi), link.y);
}

// Interior children and leaf items are offset by where this tree's nodes and items start.
void appendNodes(std::vector<glm::uvec4>& bounds, std::vector<glm::uvec4>& links, const Bvh& bvh, std::uint32_t firstNode,
                 std::uint32_t firstItem)
{
    for (const BvhNode& node : bvh.nodes) {
        const glm::uvec2 link(node.first + (node.leaf() ? firstItem : firstNode), node.count);
        appendBounds(bounds, node.bounds, link);
        links.emplace_back(link, 0u, 0u);
    }
}

void appendNodes(FlatTopLevel& out, const Bvh& bvh, std::uint32_t firstNode, std::uint32_t firstItem)
{
    appendNodes(out.nodeBounds, out.nodeLinks, bvh, firstNode, firstItem);
}

// Appends to arrays that flattenScene reserved beforehand, so nothing is copied twice.
void appendMesh(FlatScene& scene, const MeshBvh& mesh)
{
    const FlatMeshRange range{static_cast<std::uint32_t>(scene.nodeLinks.size()),
                              static_cast<std::uint32_t>(mesh.bvh.nodes.size()),
                              static_cast<std::uint32_t>(scene.triangleVertices.size()),
                              scene.meshes.empty() ? 0u : scene.meshes.back().firstVertex + scene.meshes.back().vertexCount,
                              static_cast<std::uint32_t>(mesh.triangles.triangleCount()),
                              static_cast<std::uint32_t>(mesh.triangles.positions.size())};
    appendNodes(scene.nodeBounds, scene.nodeLinks, mesh.bvh, range.rootNode, range.firstSlot);
    for (std::uint32_t triangle : mesh.bvh.itemOrder) {
        const glm::uvec3 tri = mesh.triangles.triangles[triangle];
        for (int k = 0; k < 3; ++k) scene.trianglePositions.emplace_back(mesh.triangles.positions[tri[k]], 0.0f);
        scene.triangleVertices.emplace_back(tri + range.firstVertex, mesh.triangles.materials[triangle]);
        scene.slotTriangle.push_back(triangle);
    }
    scene.meshes.push_back(range);
}

void appendInstance(std::vector<glm::uvec4>& out, const Instance& instance, const std::vector<FlatMeshRange>& meshes)
{
    const glm::mat4 localFromWorld = glm::inverse(instance.worldFromLocal);
    for (int r = 0; r < 3; ++r) {
        out.emplace_back(std::bit_cast<std::uint32_t>(localFromWorld[0][r]), std::bit_cast<std::uint32_t>(localFromWorld[1][r]),
                         std::bit_cast<std::uint32_t>(localFromWorld[2][r]), std::bit_cast<std::uint32_t>(localFromWorld[3][r]));
    }
    const std::uint32_t target = instance.kind == kInstanceMesh ? meshes.at(instance.target).rootNode : instance.target;
    const std::uint32_t flags = glm::determinant(instance.worldFromLocal) < 0.0f ? kInstanceMirrored : 0u;
    out.emplace_back(instance.kind, target, instance.objectId, flags);
}

} // namespace

FlatTopLevel flattenTopLevel(const TopLevel& topLevel, const std::vector<FlatMeshRange>& meshes, std::uint32_t topLevelRoot)
{
    FlatTopLevel out;
    // Top-level leaves hold one instance each: their `first` is the instance index itself.
    Bvh leaves = topLevel.bvh;
    for (BvhNode& node : leaves.nodes)
        if (node.leaf()) node.first = leaves.itemOrder[node.first];
    appendNodes(out, leaves, topLevelRoot, 0);
    for (const Instance& instance : topLevel.instances) appendInstance(out.instances, instance, meshes);
    return out;
}

FlatScene flattenScene(const std::vector<MeshBvh>& meshes, const TopLevel& topLevel)
{
    FlatScene scene;
    std::size_t nodes = topLevel.bvh.nodes.size(), triangles = 0;
    for (const MeshBvh& mesh : meshes) {
        nodes += mesh.bvh.nodes.size();
        triangles += mesh.bvh.itemOrder.size();
    }
    scene.nodeBounds.reserve(2 * nodes);
    scene.nodeLinks.reserve(nodes);
    scene.trianglePositions.reserve(3 * triangles);
    scene.triangleVertices.reserve(triangles);
    scene.slotTriangle.reserve(triangles);
    scene.meshes.reserve(meshes.size());
    for (const MeshBvh& mesh : meshes) appendMesh(scene, mesh);
    scene.meshNodeCount = static_cast<std::uint32_t>(scene.nodeLinks.size());
    replaceTopLevel(scene, flattenTopLevel(topLevel, scene.meshes, scene.meshNodeCount));
    return scene;
}

void replaceTopLevel(FlatScene& scene, FlatTopLevel topLevel)
{
    scene.nodeBounds.resize(std::size_t{2} * scene.meshNodeCount);
    scene.nodeLinks.resize(scene.meshNodeCount);
    scene.nodeBounds.insert(scene.nodeBounds.end(), topLevel.nodeBounds.begin(), topLevel.nodeBounds.end());
    scene.nodeLinks.insert(scene.nodeLinks.end(), topLevel.nodeLinks.begin(), topLevel.nodeLinks.end());
    scene.instances = std::move(topLevel.instances);
    scene.topLevelRoot = scene.instances.empty() ? -1 : static_cast<std::int32_t>(scene.meshNodeCount);
}

} // namespace glint::bvh
