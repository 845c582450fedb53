#pragma once
// Commands that change the hierarchy: add, remove, duplicate and reparent nodes.
#include "command.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace glint {

// Adds one node (with its component) under `parent` at `index` among its siblings. A node id
// of 0 takes a fresh id on the first apply; later applies (redo, replay) reuse it.
class AddNode final : public Command {
public:
    explicit AddNode(Node node, NodeId parent = {}, std::size_t index = SIZE_MAX);
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override;
    std::string typeName() const override { return "add_node"; }
    std::size_t memoryBytes() const override;
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);
    NodeId nodeId() const { return node_.id; }

private:
    Node node_;
    NodeId parent_;
    std::size_t index_;
};

// Removes a node and its whole subtree; revert restores ids, order, and the index in the
// parent. An active camera inside the subtree stops being active, and is restored by revert.
// Animation channels that target removed nodes are left as they are (they dangle until undo).
class RemoveNode final : public Command {
public:
    explicit RemoveNode(NodeId node) : node_(node) {}
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override;
    std::string typeName() const override { return "remove_node"; }
    std::size_t memoryBytes() const override;
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

private:
    NodeId node_;
    std::vector<Node> removed_; // the subtree, parents before children
    std::size_t indexInParent_ = 0;
    bool wasActiveCamera_ = false;
    NodeId activeCamera_;
};

// Copies a subtree under the same parent, right after the original, with fresh ids (assigned
// on the first apply and reused after). Assets are shared, not copied.
class DuplicateNode final : public Command {
public:
    explicit DuplicateNode(NodeId source, std::vector<NodeId> copyIds = {});
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override;
    std::string typeName() const override { return "duplicate_node"; }
    std::size_t memoryBytes() const override;
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);
    const std::vector<NodeId>& copyIds() const { return copyIds_; } // copy of the source first

private:
    NodeId source_;
    std::vector<NodeId> copyIds_; // in the order of Scene::subtree(source)
    std::string sourceName_;
};

// Moves a node under a new parent (none: a root) at `index`. With keepWorld, its local
// transform is recomputed so that it stays where it is in the world (shear is lost).
class ReparentNode final : public Command {
public:
    ReparentNode(NodeId node, NodeId newParent, std::size_t index = SIZE_MAX, bool keepWorld = true);
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override { return "Reparent"; }
    std::string typeName() const override { return "reparent_node"; }
    std::size_t memoryBytes() const override { return sizeof(*this); }
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

private:
    NodeId node_;
    NodeId newParent_;
    std::size_t index_;
    bool keepWorld_;
    NodeId oldParent_;
    std::size_t oldIndex_ = 0;
    Transform oldLocal_;
};

} // namespace glint
