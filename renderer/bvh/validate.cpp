#include "renderer/bvh/validate.h"

#include "renderer/bvh/bvh_layout.h"

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

Aabb nodeBox(const FlatScene& scene, std::uint32_t node)
{
    return Aabb{nodeCorner(scene, 2 * node), nodeCorner(scene, 2 * node + 1)};
}

bool finitePoint(const glm::vec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// The nodes [first, end) one level may use, and what its leaves may reference.
struct Level {
    const char* name;
    std::uint32_t root, firstNode, endNode;
    std::uint32_t firstItem, endItem;
    std::uint32_t maxLeaf;
};

using LeafCheck = std::function<Problem(std::uint32_t node, glm::uvec4 link)>;

// Walks the tree from its root: links stay inside the level and point forwards (so no cycle), child
// boxes lie inside their parent's, no branch is deeper than the traversal stack, leaves are sane.
Problem checkTree(const FlatScene& scene, const Level& level, const LeafCheck& checkLeaf)
{
    if (level.root < level.firstNode || level.root >= level.endNode)
        return message(level.name, ": root node ", level.root, " is outside its nodes [", level.firstNode, ", ", level.endNode, ")");
    std::vector<std::pair<std::uint32_t, int>> pending{{level.root, 1}};
    while (!pending.empty()) {
        const auto [node, depth] = pending.back();
        pending.pop_back();
        if (depth >= kStackSize) return message(level.name, ": node ", node, " is deeper than the traversal stack (", kStackSize, ")");
        const glm::uvec4 link = scene.nodeLinks[node];
        if (scene.nodeBounds[2 * node].w != link.x || scene.nodeBounds[2 * node + 1].w != link.y)
            return message(level.name, ": node ", node, "'s bounds carry another link than its link texel");
        if (link.x >= kMaxLinkFirst)
            return message(level.name, ": node ", node, " links to index ", link.x, ", beyond the ", kMaxLinkFirst, " the traversal can address");
        if (link.y > 0) {
            if (link.y > level.maxLeaf) return message(level.name, ": leaf node ", node, " holds ", link.y, " items (at most ", level.maxLeaf, ")");
            if (link.x < level.firstItem || link.x + link.y > level.endItem || link.x + link.y < link.x)
                return message(level.name, ": leaf node ", node, " references items outside [", level.firstItem, ", ", level.endItem, ")");
            if (Problem problem = checkLeaf(node, link)) return problem;
            continue;
        }
        if (link.x <= node || link.x + 1 >= level.endNode)
            return message(level.name, ": node ", node, " links to child ", link.x, ", not a later node of its level (a cycle or a bad index)");
        for (std::uint32_t child : {link.x, link.x + 1}) {
            if (!nodeBox(scene, node).contains(nodeBox(scene, child)))
                return message(level.name, ": the box of node ", child, " is not inside the box of its parent ", node);
            pending.emplace_back(child, depth + 1);
        }
    }
    return std::nullopt;
}

Problem checkSizes(const FlatScene& scene)
{
    if (scene.nodeBounds.size() != 2 * scene.nodeLinks.size()) return std::string("node bounds and node links disagree in length");
    if (scene.trianglePositions.size() != 3 * scene.triangleVertices.size() || scene.slotTriangle.size() != scene.triangleVertices.size())
        return std::string("triangle positions, vertices and slot table disagree in length");
    if (scene.instances.size() % kInstanceTexels != 0) return std::string("the instance buffer is not a whole number of instances");
    if (scene.meshNodeCount > scene.nodeLinks.size()) return std::string("more mesh nodes than nodes");
    return std::nullopt;
}

Problem checkMesh(const FlatScene& scene, std::size_t meshIndex, std::vector<bool>& slotSeen)
{
    const FlatMeshRange& mesh = scene.meshes[meshIndex];
    if (mesh.triangleCount == 0) return std::nullopt;
    const std::string name = message("mesh ", meshIndex);
    const Level level{name.c_str(), mesh.rootNode, mesh.rootNode, mesh.rootNode + mesh.nodeCount,
                      mesh.firstSlot, mesh.firstSlot + mesh.triangleCount, kMaxLeafTriangles};
    Problem problem = checkTree(scene, level, [&](std::uint32_t node, glm::uvec4 link) -> Problem {
        const Aabb box = nodeBox(scene, node);
        for (std::uint32_t slot = link.x; slot < link.x + link.y; ++slot) {
            if (slotSeen[slot]) return message(name, ": triangle slot ", slot, " is referenced twice");
            slotSeen[slot] = true;
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 p{scene.trianglePositions[3 * slot + k]};
                if (finitePoint(p) && !box.contains(Aabb{p, p}))
                    return message(name, ": triangle slot ", slot, " lies outside its leaf node ", node);
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
    for (const FlatMeshRange& mesh : scene.meshes)
        if (mesh.triangleCount > 0 && mesh.rootNode == info.y) return std::nullopt;
    return message("instance ", instance, ": node ", info.y, " is not the root of a mesh BVH");
}

Problem checkTopLevel(const FlatScene& scene)
{
    const auto instanceCount = static_cast<std::uint32_t>(scene.instances.size() / kInstanceTexels);
    if (scene.topLevelRoot < 0)
        return instanceCount == 0 ? Problem{} : Problem{"instances but no top-level root"};
    std::vector<bool> seen(instanceCount, false);
    const Level level{"top level", static_cast<std::uint32_t>(scene.topLevelRoot), scene.meshNodeCount,
                      static_cast<std::uint32_t>(scene.nodeLinks.size()), 0, instanceCount, 1};
    Problem problem = checkTree(scene, level, [&](std::uint32_t, glm::uvec4 link) -> Problem {
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

std::optional<std::string> validateTopLevel(const FlatScene& scene)
{
    if (Problem problem = checkSizes(scene)) return problem;
    return checkTopLevel(scene);
}

} // namespace glint::bvh
