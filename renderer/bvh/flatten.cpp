#include "renderer/bvh/flat_scene.h"

#include "renderer/bvh/bvh_layout.h"

#include <bit>

namespace glint::bvh {
namespace {

// The builders keep every box within kGridReach (box_grid.h), and a level's grid is built around
// its root, which holds every box of the level: quantize() cannot fail here. Were it to, the whole
// grid is the widest box a node can have.
glm::uvec3 gridBits(const BoxGrid& grid, const Aabb& box)
{
    const std::optional<GridBox> q = quantize(grid, box);
    return packGridBox(q ? *q : GridBox{glm::uvec3(0), glm::uvec3(kGridMax)});
}

std::uint32_t linkOf(const BvhNode& node, std::uint32_t firstNode, std::uint32_t firstItem)
{
    return packLink(glm::uvec2(node.first + (node.leaf() ? firstItem : firstNode), node.count));
}

// Interior children and leaf items are offset by where this tree's nodes and items start. Appends
// the level's texels: the root's exact lower corner and link, the grid's scale and the root's index.
void appendLevel(std::vector<glm::uvec4>& nodes, std::vector<glm::uvec4>& levels, const Bvh& bvh, std::uint32_t firstNode,
                 std::uint32_t firstItem)
{
    const BoxGrid grid = bvh.nodes.empty() ? BoxGrid{} : gridAround(bvh.nodes[0].bounds);
    for (const BvhNode& node : bvh.nodes) nodes.emplace_back(gridBits(grid, node.bounds), linkOf(node, firstNode, firstItem));
    const std::uint32_t rootLink = bvh.nodes.empty() ? 0u : linkOf(bvh.nodes[0], firstNode, firstItem);
    levels.emplace_back(std::bit_cast<glm::uvec3>(grid.origin), rootLink);
    levels.emplace_back(std::bit_cast<glm::uvec3>(grid.scale), firstNode);
}

// Appends to arrays that flattenScene reserved beforehand, so nothing is copied twice.
void appendMesh(FlatScene& scene, const MeshBvh& mesh)
{
    const FlatMeshRange range{static_cast<std::uint32_t>(scene.nodes.size()),
                              static_cast<std::uint32_t>(mesh.bvh.nodes.size()),
                              static_cast<std::uint32_t>(scene.triangleVertices.size()),
                              scene.meshes.empty() ? 0u : scene.meshes.back().firstVertex + scene.meshes.back().vertexCount,
                              static_cast<std::uint32_t>(mesh.triangles.triangleCount()),
                              static_cast<std::uint32_t>(mesh.triangles.positions.size())};
    appendLevel(scene.nodes, scene.levels, mesh.bvh, range.rootNode, range.firstSlot);
    for (std::uint32_t triangle : mesh.bvh.itemOrder) {
        const glm::uvec3 tri = mesh.triangles.triangles[triangle];
        for (int k = 0; k < 3; ++k) scene.trianglePositions.emplace_back(mesh.triangles.positions[tri[k]], 0.0f);
        scene.triangleVertices.emplace_back(tri + range.firstVertex, mesh.triangles.materials[triangle]);
        scene.slotTriangle.push_back(triangle);
    }
    scene.meshes.push_back(range);
}

void appendInstance(std::vector<glm::uvec4>& out, const Instance& instance)
{
    const glm::mat4 localFromWorld = glm::inverse(instance.worldFromLocal);
    for (int r = 0; r < 3; ++r) {
        out.emplace_back(std::bit_cast<std::uint32_t>(localFromWorld[0][r]), std::bit_cast<std::uint32_t>(localFromWorld[1][r]),
                         std::bit_cast<std::uint32_t>(localFromWorld[2][r]), std::bit_cast<std::uint32_t>(localFromWorld[3][r]));
    }
    const std::uint32_t flags = glm::determinant(instance.worldFromLocal) < 0.0f ? kInstanceMirrored : 0u;
    out.emplace_back(instance.kind, instance.target, instance.objectId, flags);
}

} // namespace

FlatTopLevel flattenTopLevel(const TopLevel& topLevel, std::uint32_t firstNode)
{
    FlatTopLevel out;
    // Top-level leaves hold one instance each: their `first` is the instance index itself.
    Bvh leaves = topLevel.bvh;
    for (BvhNode& node : leaves.nodes)
        if (node.leaf()) node.first = leaves.itemOrder[node.first];
    appendLevel(out.nodes, out.level, leaves, firstNode, 0);
    for (const Instance& instance : topLevel.instances) appendInstance(out.instances, instance);
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
    scene.nodes.reserve(nodes);
    scene.levels.reserve(kLevelTexels * (meshes.size() + 1));
    scene.trianglePositions.reserve(3 * triangles);
    scene.triangleVertices.reserve(triangles);
    scene.slotTriangle.reserve(triangles);
    scene.meshes.reserve(meshes.size());
    for (const MeshBvh& mesh : meshes) appendMesh(scene, mesh);
    scene.meshNodeCount = static_cast<std::uint32_t>(scene.nodes.size());
    replaceTopLevel(scene, flattenTopLevel(topLevel, scene.meshNodeCount));
    return scene;
}

void replaceTopLevel(FlatScene& scene, FlatTopLevel topLevel)
{
    scene.nodes.resize(scene.meshNodeCount);
    scene.levels.resize(kLevelTexels * scene.meshes.size());
    scene.nodes.insert(scene.nodes.end(), topLevel.nodes.begin(), topLevel.nodes.end());
    scene.levels.insert(scene.levels.end(), topLevel.level.begin(), topLevel.level.end());
    scene.instances = std::move(topLevel.instances);
    scene.topLevel = scene.instances.empty() ? -1 : static_cast<std::int32_t>(scene.meshes.size());
}

} // namespace glint::bvh
