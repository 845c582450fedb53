#include "renderer/bvh/validate.h"

#include "renderer/bvh/bvh_layout.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

namespace glint::bvh {
namespace {

using Problem = std::optional<std::string>;

template <class... Parts>
std::string message(const Parts&... parts)
{
    std::ostringstream out;
    (out << ... << parts);
    return out.str();
}

// A power of two: the grid's points are then one rounding from exact on the CPU and the GPU alike.
bool powerOfTwo(float scale)
{
    int exponent = 0;
    return std::isfinite(scale) && scale > 0.0f && std::frexp(scale, &exponent) == 0.5f;
}

// The nodes [first, end) one level may use, and what its leaves may reference.
struct Level {
    const char* name;
    std::uint32_t index; // in the level buffer
    std::uint32_t root, firstNode, endNode;
    std::uint32_t firstItem, endItem;
    std::uint32_t maxLeaf;
};

// `box`: the leaf's box as a walk tests it.
using LeafCheck = std::function<Problem(std::uint32_t node, glm::uvec2 link, const Aabb& box)>;

Problem checkGrid(const FlatScene& scene, const Level& level, const BoxGrid& grid)
{
    if (!withinGridReach(Aabb{grid.origin, grid.origin}) || !powerOfTwo(grid.scale.x) || !powerOfTwo(grid.scale.y) ||
        !powerOfTwo(grid.scale.z))
        return message(level.name, ": its box grid is not a finite origin with power-of-two steps");
    if (levelRootNode(scene, level.index) != level.root || levelRootLink(scene, level.index) != nodeLink(scene, level.root))
        return message(level.name, ": its level texels and its root node ", level.root, " disagree");
    return std::nullopt;
}

// Walks the tree from its root: links stay inside the level and point forwards (so no cycle), child
// boxes lie inside their parent's, no branch is deeper than the traversal stack, leaves are sane.
Problem checkTree(const FlatScene& scene, const Level& level, const LeafCheck& checkLeaf)
{
    if (level.root < level.firstNode || level.root >= level.endNode)
        return message(level.name, ": root node ", level.root, " is outside its nodes [", level.firstNode, ", ", level.endNode, ")");
    const BoxGrid grid = levelGrid(scene, level.index);
    if (Problem problem = checkGrid(scene, level, grid)) return problem;
    std::vector<std::pair<std::uint32_t, int>> pending{{level.root, 1}};
    while (!pending.empty()) {
        const auto [node, depth] = pending.back();
        pending.pop_back();
        if (depth >= kStackSize) return message(level.name, ": node ", node, " is deeper than the traversal stack (", kStackSize, ")");
        const glm::uvec2 link = nodeLink(scene, node);
        if (link.y > 0) {
            if (link.y > level.maxLeaf) return message(level.name, ": leaf node ", node, " holds ", link.y, " items (at most ", level.maxLeaf, ")");
            if (link.x < level.firstItem || link.x + link.y > level.endItem || link.x + link.y < link.x)
                return message(level.name, ": leaf node ", node, " references items outside [", level.firstItem, ", ", level.endItem, ")");
            if (Problem problem = checkLeaf(node, link, nodeBox(scene, grid, node))) return problem;
            continue;
        }
        if (link.x <= node || link.x + 1 >= level.endNode)
            return message(level.name, ": node ", node, " links to child ", link.x, ", not a later node of its level (a cycle or a bad index)");
        for (std::uint32_t child : {link.x, link.x + 1}) {
            if (!nodeBox(scene, grid, node).contains(nodeBox(scene, grid, child)))
                return message(level.name, ": the box of node ", child, " is not inside the box of its parent ", node);
            pending.emplace_back(child, depth + 1);
        }
    }
    return std::nullopt;
}

Problem checkSizes(const FlatScene& scene)
{
    if (scene.levels.size() != kLevelTexels * (scene.meshes.size() + 1))
        return std::string("the level buffer does not hold one level per mesh and the top level");
    if (scene.trianglePositions.size() != 3 * scene.triangleVertices.size() || scene.slotTriangle.size() != scene.triangleVertices.size())
        return std::string("triangle positions, vertices and slot table disagree in length");
    if (scene.instances.size() % kInstanceTexels != 0) return std::string("the instance buffer is not a whole number of instances");
    if (scene.meshNodeCount > scene.nodes.size()) return std::string("more mesh nodes than nodes");
    return checkLinkReach(scene.nodes.size(), scene.triangleVertices.size(), scene.instances.size() / kInstanceTexels);
}

Problem checkMesh(const FlatScene& scene, std::size_t meshIndex, std::vector<bool>& slotSeen)
{
    const FlatMeshRange& mesh = scene.meshes[meshIndex];
    if (mesh.triangleCount == 0) return std::nullopt;
    const std::string name = message("mesh ", meshIndex);
    const Level level{name.c_str(), static_cast<std::uint32_t>(meshIndex), mesh.rootNode, mesh.rootNode, mesh.rootNode + mesh.nodeCount,
                      mesh.firstSlot, mesh.firstSlot + mesh.triangleCount, kMaxLeafTriangles};
    Problem problem = checkTree(scene, level, [&](std::uint32_t node, glm::uvec2 link, const Aabb& box) -> Problem {
        for (std::uint32_t slot = link.x; slot < link.x + link.y; ++slot) {
            if (slotSeen[slot]) return message(name, ": triangle slot ", slot, " is referenced twice");
            slotSeen[slot] = true;
            // Bounded as the builder bounds it: non-finite coordinates drop out, and a triangle
            // beyond the grid's reach is in no box.
            Aabb triangle;
            for (int k = 0; k < 3; ++k) triangle.grow(glm::vec3(scene.trianglePositions[3 * slot + k]));
            if (withinGridReach(triangle) && !box.contains(triangle))
                return message(name, ": triangle slot ", slot, " lies outside its leaf node ", node);
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t vertex = scene.triangleVertices[slot][k];
                if (vertex < mesh.firstVertex || vertex >= mesh.firstVertex + mesh.vertexCount)
                    return message(name, ": triangle slot ", slot, " uses vertex ", vertex, " of another mesh");
            }
        }
        return std::nullopt;
    });
    if (problem) return problem;
    for (std::uint32_t slot = mesh.firstSlot; slot < mesh.firstSlot + mesh.triangleCount; ++slot)
        if (!slotSeen[slot]) return message(name, ": triangle slot ", slot, " is in no leaf");
    return std::nullopt;
}

Problem checkInstance(const FlatScene& scene, std::uint32_t instance)
{
    const glm::uvec4 info = scene.instances[kInstanceTexels * instance + 3];
    if (info.x == kInstanceShape) return std::nullopt;
    if (info.x != kInstanceMesh) return message("instance ", instance, ": unknown kind ", info.x);
    if (info.y < scene.meshes.size() && scene.meshes[info.y].triangleCount > 0) return std::nullopt;
    return message("instance ", instance, ": mesh ", info.y, " does not exist or has no triangles");
}

Problem checkTopLevel(const FlatScene& scene)
{
    const auto instanceCount = static_cast<std::uint32_t>(scene.instances.size() / kInstanceTexels);
    if (scene.topLevel < 0)
        return instanceCount == 0 ? Problem{} : Problem{"instances but no top level"};
    if (static_cast<std::size_t>(scene.topLevel) != scene.meshes.size())
        return message("the top level is level ", scene.topLevel, ", not ", scene.meshes.size(), " (after the meshes)");
    std::vector<bool> seen(instanceCount, false);
    const Level level{"top level", static_cast<std::uint32_t>(scene.topLevel), scene.meshNodeCount, scene.meshNodeCount,
                      static_cast<std::uint32_t>(scene.nodes.size()), 0, instanceCount, 1};
    Problem problem = checkTree(scene, level, [&](std::uint32_t, glm::uvec2 link, const Aabb&) -> Problem {
        if (seen[link.x]) return message("top level: instance ", link.x, " is referenced twice");
        seen[link.x] = true;
        return checkInstance(scene, link.x);
    });
    if (problem) return problem;
    for (std::uint32_t i = 0; i < instanceCount; ++i)
        if (!seen[i]) return message("top level: instance ", i, " is in no leaf");
    return std::nullopt;
}

} // namespace

std::optional<std::string> validateFlatScene(const FlatScene& scene)
{
    if (Problem problem = checkSizes(scene)) return problem;
    std::vector<bool> slotSeen(scene.triangleVertices.size(), false);
    for (std::size_t mesh = 0; mesh < scene.meshes.size(); ++mesh)
        if (Problem problem = checkMesh(scene, mesh, slotSeen)) return problem;
    return checkTopLevel(scene);
}

// A packed link holds `first` below kMaxLinkFirst: past that, links would wrap unnoticed.
std::optional<std::string> checkLinkReach(std::size_t nodes, std::size_t slots, std::size_t instances)
{
    const std::size_t largest = std::max({nodes, slots, instances});
    if (largest <= kMaxLinkFirst) return std::nullopt;
    return message("the scene needs links to index ", largest - 1, ", beyond the ", kMaxLinkFirst, " the traversal can address");
}

std::optional<std::string> validateTopLevel(const FlatScene& scene)
{
    if (Problem problem = checkSizes(scene)) return problem;
    return checkTopLevel(scene);
}

} // namespace glint::bvh
