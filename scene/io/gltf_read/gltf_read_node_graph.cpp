// The node hierarchy must be a forest: glTF forbids shared children and cycles, and following a
// cycle would never end.
#include "gltf_read_json.h"
#include "gltf_read_nodes.h"

#include <set>

namespace glint {

namespace {

std::size_t countOf(const Json& doc, const char* key) { return doc.contains(key) ? doc[key].size() : 0; }

// Walks up from every node once (linear time even for a chain of a million nodes): meeting a node
// of the walk in progress again is a loop.
void requireNoLoop(const GltfReadContext& ctx, const std::vector<int>& parents)
{
    enum class Mark : std::uint8_t { Unseen, OnWalk, Done };
    std::vector<Mark> marks(parents.size(), Mark::Unseen);
    std::vector<std::size_t> walk;
    for (std::size_t start = 0; start < parents.size(); ++start) {
        walk.clear();
        for (int at = static_cast<int>(start); at >= 0 && marks[static_cast<std::size_t>(at)] != Mark::Done; at = parents[static_cast<std::size_t>(at)]) {
            if (marks[static_cast<std::size_t>(at)] == Mark::OnWalk)
                ctx.fail("node-graph-cycle", "node " + std::to_string(at) + " is its own ancestor: the node hierarchy has a cycle");
            marks[static_cast<std::size_t>(at)] = Mark::OnWalk;
            walk.push_back(static_cast<std::size_t>(at));
        }
        for (std::size_t n : walk) marks[n] = Mark::Done;
    }
}

// Parents before children, siblings in order; iterative, so a deep hierarchy cannot exhaust the stack.
void collectDepthFirst(const Json& doc, int root, std::vector<int>& out)
{
    std::vector<int> pending{root};
    while (!pending.empty()) {
        const int node = pending.back();
        pending.pop_back();
        out.push_back(node);
        const Json& json = doc["nodes"][static_cast<std::size_t>(node)];
        if (!json.contains("children")) continue;
        const Json& children = json["children"];
        for (auto it = children.rbegin(); it != children.rend(); ++it) pending.push_back(it->get<int>());
    }
}

std::vector<int> defaultSceneRoots(GltfReadContext& ctx, const std::vector<int>& parents)
{
    const JsonReader json{ctx.file};
    const std::size_t scenes = countOf(ctx.doc, "scenes");
    std::vector<int> roots;
    if (scenes == 0) {
        for (std::size_t i = 0; i < parents.size(); ++i)
            if (parents[i] < 0) roots.push_back(static_cast<int>(i));
        ctx.warn("no-scene", roots.empty() ? "the file has no scene and no nodes: the scene is empty"
                                           : "the file has no scene: its " + std::to_string(roots.size()) + " root nodes are loaded");
        return roots;
    }
    const int chosen = std::max(0, json.index(ctx.doc, "scene", "the glTF"));
    const Json& scene = ctx.doc["scenes"][static_cast<std::size_t>(chosen)];
    ctx.scene.name = json.string(scene, "name", "scenes[" + std::to_string(chosen) + "]");
    for (std::size_t i = 0; i < scenes; ++i)
        if (static_cast<int>(i) != chosen) ctx.drop("scene-dropped", "scene " + std::to_string(i) + " is not the default scene: only scene " + std::to_string(chosen) + " is loaded");
    std::set<int> seen;
    if (scene.contains("nodes")) {
        for (const Json& n : scene["nodes"]) {
            const int node = n.get<int>();
            if (parents[static_cast<std::size_t>(node)] >= 0 || !seen.insert(node).second)
                ctx.fail("node-graph-cycle", "scene " + std::to_string(chosen) + " lists node " + std::to_string(node) + " as a root, but it is a child or listed twice");
            roots.push_back(node);
        }
    }
    if (roots.empty()) ctx.warn("no-scene", "the default scene has no nodes: the scene is empty");
    return roots;
}

} // namespace

std::vector<int> nodeParents(const GltfReadContext& ctx)
{
    const std::size_t count = countOf(ctx.doc, "nodes");
    std::vector<int> parents(count, -1);
    for (std::size_t i = 0; i < count; ++i) {
        const Json& node = ctx.doc["nodes"][i];
        if (!node.contains("children")) continue;
        if (!node["children"].is_array()) ctx.fail("wrong-type", "nodes[" + std::to_string(i) + "].children must be an array");
        for (const Json& c : node["children"]) {
            const auto child = c.get<std::size_t>();
            if (child == i) ctx.fail("node-graph-cycle", "node " + std::to_string(i) + " lists itself as a child");
            if (parents[child] >= 0)
                ctx.fail("node-graph-cycle", "node " + std::to_string(child) + " is a child of both node " + std::to_string(parents[child]) + " and node " + std::to_string(i));
            parents[child] = static_cast<int>(i);
        }
    }
    requireNoLoop(ctx, parents);
    return parents;
}

std::vector<int> nodesToLoad(GltfReadContext& ctx, const std::vector<int>& parents)
{
    std::vector<int> order;
    for (int root : defaultSceneRoots(ctx, parents)) collectDepthFirst(ctx.doc, root, order);
    std::vector<bool> loaded(parents.size());
    for (int n : order) loaded[static_cast<std::size_t>(n)] = true;
    for (std::size_t i = 0; i < parents.size(); ++i)
        if (!loaded[i]) ctx.drop("node-dropped", "node " + std::to_string(i) + " is not part of the default scene");
    return order;
}

std::vector<NodeId> assignNodeIds(GltfReadContext& ctx, const std::vector<int>& loaded)
{
    const JsonReader json{ctx.file};
    std::vector<NodeId> ids(countOf(ctx.doc, "nodes"));
    std::set<std::uint32_t> taken;
    for (int n : loaded) {
        const std::string where = "nodes[" + std::to_string(n) + "]";
        const Json* ext = json.extension(ctx.doc["nodes"][static_cast<std::size_t>(n)], "GLINT_node", where);
        const std::uint64_t id = ext ? json.unsignedNumber(*ext, "id", 0, where + ".extensions.GLINT_node") : 0;
        if (id == 0 || id > UINT32_MAX) continue;
        if (!taken.insert(static_cast<std::uint32_t>(id)).second) ctx.warn("duplicate-node-id", where + " repeats node id " + std::to_string(id) + ": it gets a new one");
        else ids[static_cast<std::size_t>(n)] = NodeId{static_cast<std::uint32_t>(id)};
    }
    std::uint32_t next = taken.empty() ? 1 : *taken.rbegin() + 1;
    for (int n : loaded) {
        NodeId& id = ids[static_cast<std::size_t>(n)];
        if (id.valid()) continue;
        const auto preferred = static_cast<std::uint32_t>(n) + 1;
        id = NodeId{taken.insert(preferred).second ? preferred : next};
        taken.insert(id.value);
        next = std::max(next, *taken.rbegin() + 1);
    }
    return ids;
}

} // namespace glint
