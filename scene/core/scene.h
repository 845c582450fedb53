#pragma once
// The document: a node hierarchy plus shared assets, animations and project settings.
// Plain data with one invariant kept by this class: the hierarchy is a forest (parents and
// children agree, no cycles) and world transforms are cached and invalidated with it.
// Not thread-safe: hand worker threads a copy.
#include "animation.h"
#include "asset_table.h"
#include "diagnostics.h"
#include "image.h"
#include "material.h"
#include "mesh.h"
#include "node.h"
#include "settings.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace glint {

class Scene {
public:
    // --- nodes -------------------------------------------------------------------------------
    const Node* node(NodeId id) const;
    const Node& at(NodeId id) const; // throws std::out_of_range
    bool contains(NodeId id) const { return nodes_.count(id) != 0; }
    std::size_t nodeCount() const { return nodes_.size(); }
    const std::vector<NodeId>& roots() const { return roots_; }
    const std::map<NodeId, Node>& nodes() const { return nodes_; }

    // Adds a node under `parent` (none: a root) at `index` among its siblings (clamped).
    // node.id 0 assigns a fresh id; a given id must be free. node.parent/children are ignored.
    NodeId addNode(Node node, NodeId parent = {}, std::size_t index = SIZE_MAX);
    // Removes a node that has no children and returns it (parent set, children empty).
    Node removeLeaf(NodeId id);
    // Moves a node under a new parent (none: root) at index. Refuses cycles (std::invalid_argument).
    // The local transform is kept as is; preserving the world transform is the caller's choice.
    void setParent(NodeId id, NodeId parent, std::size_t index = SIZE_MAX);
    std::size_t indexInParent(NodeId id) const;

    void setLocal(NodeId id, const Transform& local);
    void setName(NodeId id, std::string name);
    void setVisible(NodeId id, bool visible);
    void setComponent(NodeId id, Component component);
    void setUnknown(NodeId id, nlohmann::json unknown);
    // Edit the component in place (no hierarchy or transform change, so no cache to invalidate).
    Component& component(NodeId id);

    // Both cached, and computed without recursion: linear in the depth once, so a chain of a
    // hundred thousand nodes costs no more than as many siblings.
    glm::mat4 worldFromNode(NodeId id) const;
    bool visibleInWorld(NodeId id) const; // the node and every ancestor are visible
    bool isAncestor(NodeId ancestor, NodeId id) const;
    std::vector<NodeId> subtree(NodeId id) const; // id first, then descendants depth-first
    std::vector<NodeId> depthFirst() const;        // every node, roots in order
    std::optional<NodeId> findByName(const std::string& name) const;
    NodeId peekNextNodeId() const { return NodeId{nextNodeId_}; }

    // --- assets -----------------------------------------------------------------------------
    AssetTable<MeshId, Mesh> meshes;
    AssetTable<MaterialId, Material> materials;
    AssetTable<TextureId, Texture> textures;
    AssetTable<ImageId, Image> images;
    AssetTable<SamplerId, Sampler> samplers;
    AssetTable<AnimationId, Animation> animations;

    // --- document-level data ---------------------------------------------------------------
    std::string name;         // glTF scene name
    ProjectSettings settings; // the project file
    nlohmann::json unknown;   // glTF asset info, top-level extensions/extras Glint does not interpret
    // What the loaded file held that Glint cannot keep (skins, morph targets, ...): the next save
    // names each of these in its report. Bookkeeping, not content: not compared by operator==.
    Warnings unsupported;

    friend bool operator==(const Scene& a, const Scene& b);

private:
    Node& mutableNode(NodeId id);
    void invalidateCaches(NodeId id) const; // the node's subtree
    template <class Value, class Step>
    Value cachedDownTheHierarchy(NodeId id, std::map<NodeId, Value>& cache, Value rootValue, Step step) const;
    void detach(Node& n);
    void attach(Node& n, NodeId parent, std::size_t index);

    std::map<NodeId, Node> nodes_;
    std::vector<NodeId> roots_;
    std::uint32_t nextNodeId_ = 1;
    mutable std::map<NodeId, glm::mat4> worldCache_;
    mutable std::map<NodeId, bool> visibleCache_;
};

} // namespace glint
