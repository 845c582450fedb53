#include "node_commands.h"

#include "component_changes.h"
#include "memory_estimate.h"
#include "value_json.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace glint {

// --- AddNode ------------------------------------------------------------------------------------

AddNode::AddNode(Node node, NodeId parent, std::size_t index)
    : node_(std::move(node)), parent_(parent), index_(index) {
    node_.parent = {};
    node_.children.clear();
}

ChangeSet AddNode::apply(Scene& scene) {
    node_.id = scene.addNode(node_, parent_, index_);
    return componentChange(node_.id, node_.component).add(Change::Structure);
}

ChangeSet AddNode::revert(Scene& scene) {
    scene.removeLeaf(node_.id);
    return componentChange(node_.id, node_.component).add(Change::Structure);
}

std::string AddNode::label() const { return "Add " + node_.name; }
std::size_t AddNode::memoryBytes() const { return sizeof(*this) + approxBytes(node_); }

nlohmann::json AddNode::toJson() const { return {{"node", node_}, {"parent", parent_}, {"index", index_}}; }

CommandPtr AddNode::fromJson(const nlohmann::json& j) {
    return std::make_unique<AddNode>(j.at("node").get<Node>(), j.at("parent").get<NodeId>(),
                                     j.at("index").get<std::size_t>());
}

// --- RemoveNode ---------------------------------------------------------------------------------

ChangeSet RemoveNode::apply(Scene& scene) {
    const std::vector<NodeId> ids = scene.subtree(node_);
    if (ids.empty()) throw std::out_of_range("RemoveNode: no node " + std::to_string(node_.value));
    indexInParent_ = scene.indexInParent(node_);
    removed_.clear();
    ChangeSet changes;
    changes.add(Change::Structure);
    for (NodeId id : ids) {
        removed_.push_back(scene.at(id));
        changes.merge(componentChange(id, removed_.back().component));
    }
    activeCamera_ = scene.settings.activeCamera;
    wasActiveCamera_ = std::find(ids.begin(), ids.end(), activeCamera_) != ids.end();
    for (auto it = ids.rbegin(); it != ids.rend(); ++it) scene.removeLeaf(*it);
    if (wasActiveCamera_) {
        scene.settings.activeCamera = {};
        changes.add(Change::Camera);
    }
    return changes;
}

ChangeSet RemoveNode::revert(Scene& scene) {
    ChangeSet changes;
    changes.add(Change::Structure);
    for (std::size_t i = 0; i < removed_.size(); ++i) {
        const Node& n = removed_[i];
        scene.addNode(n, n.parent, i == 0 ? indexInParent_ : SIZE_MAX);
        changes.merge(componentChange(n.id, n.component));
    }
    if (wasActiveCamera_) {
        scene.settings.activeCamera = activeCamera_;
        changes.add(Change::Camera);
    }
    return changes;
}

std::string RemoveNode::label() const { return removed_.empty() ? "Remove" : "Remove " + removed_.front().name; }

std::size_t RemoveNode::memoryBytes() const {
    std::size_t bytes = sizeof(*this);
    for (const Node& n : removed_) bytes += approxBytes(n);
    return bytes;
}

nlohmann::json RemoveNode::toJson() const { return {{"node", node_}}; }

CommandPtr RemoveNode::fromJson(const nlohmann::json& j) {
    return std::make_unique<RemoveNode>(j.at("node").get<NodeId>());
}

// --- DuplicateNode ------------------------------------------------------------------------------

DuplicateNode::DuplicateNode(NodeId source, std::vector<NodeId> copyIds)
    : source_(source), copyIds_(std::move(copyIds)) {}

ChangeSet DuplicateNode::apply(Scene& scene) {
    const std::vector<NodeId> originals = scene.subtree(source_);
    if (originals.empty()) throw std::out_of_range("DuplicateNode: no node " + std::to_string(source_.value));
    const bool fresh = copyIds_.empty();
    if (!fresh && copyIds_.size() != originals.size())
        throw std::invalid_argument("DuplicateNode: the recorded copy ids do not fit the subtree");
    // Recorded ids (a replayed log) must each name a new node: valid, unused and not repeated.
    for (std::size_t i = 0; i < copyIds_.size(); ++i) {
        const NodeId id = copyIds_[i];
        if (!id.valid() || scene.contains(id) || std::find(copyIds_.begin(), copyIds_.begin() + std::ptrdiff_t(i), id) != copyIds_.begin() + std::ptrdiff_t(i))
            throw std::invalid_argument("DuplicateNode: recorded copy id " + std::to_string(id.value) + " is invalid, taken or repeated");
    }

    sourceName_ = scene.at(source_).name;
    std::map<NodeId, NodeId> copyFromOriginal;
    ChangeSet changes;
    changes.add(Change::Structure);
    for (std::size_t i = 0; i < originals.size(); ++i) {
        Node copy = scene.at(originals[i]);
        copy.id = fresh ? NodeId{} : copyIds_[i];
        const bool top = i == 0;
        const NodeId parent = top ? copy.parent : copyFromOriginal.at(copy.parent);
        const std::size_t index = top ? scene.indexInParent(source_) + 1 : SIZE_MAX;
        const NodeId id = scene.addNode(copy, parent, index);
        copyFromOriginal[originals[i]] = id;
        if (fresh) copyIds_.push_back(id);
        changes.merge(componentChange(id, copy.component));
    }
    return changes;
}

ChangeSet DuplicateNode::revert(Scene& scene) {
    ChangeSet changes;
    changes.add(Change::Structure);
    for (auto it = copyIds_.rbegin(); it != copyIds_.rend(); ++it) {
        const Node removed = scene.removeLeaf(*it);
        changes.merge(componentChange(removed.id, removed.component));
    }
    return changes;
}

std::string DuplicateNode::label() const { return "Duplicate " + sourceName_; }
std::size_t DuplicateNode::memoryBytes() const { return sizeof(*this) + copyIds_.size() * sizeof(NodeId); }

nlohmann::json DuplicateNode::toJson() const { return {{"source", source_}, {"copies", copyIds_}}; }

CommandPtr DuplicateNode::fromJson(const nlohmann::json& j) {
    return std::make_unique<DuplicateNode>(j.at("source").get<NodeId>(), j.at("copies").get<std::vector<NodeId>>());
}

// --- ReparentNode -------------------------------------------------------------------------------

ReparentNode::ReparentNode(NodeId node, NodeId newParent, std::size_t index, bool keepWorld)
    : node_(node), newParent_(newParent), index_(index), keepWorld_(keepWorld) {}

ChangeSet ReparentNode::apply(Scene& scene) {
    const Node& n = scene.at(node_);
    if (newParent_ && !scene.contains(newParent_)) throw std::out_of_range("ReparentNode: no parent");
    oldParent_ = n.parent;
    oldIndex_ = scene.indexInParent(node_);
    oldLocal_ = n.local;

    // Same parent: the world transform cannot change, and recomputing would only add rounding.
    const bool recompute = keepWorld_ && newParent_ != oldParent_;
    Transform newLocal = oldLocal_;
    if (recompute) {
        const glm::mat4 parentFromWorld = newParent_ ? glm::inverse(scene.worldFromNode(newParent_)) : glm::mat4(1.0f);
        newLocal = fromMatrix(parentFromWorld * scene.worldFromNode(node_));
    }
    scene.setParent(node_, newParent_, index_); // throws on a cycle, before changing anything
    if (recompute) scene.setLocal(node_, newLocal);
    return nodeChange(Change::Structure, node_).add(Change::Transform);
}

ChangeSet ReparentNode::revert(Scene& scene) {
    scene.setParent(node_, oldParent_, oldIndex_);
    scene.setLocal(node_, oldLocal_);
    return nodeChange(Change::Structure, node_).add(Change::Transform);
}

nlohmann::json ReparentNode::toJson() const {
    return {{"node", node_}, {"parent", newParent_}, {"index", index_}, {"keepWorld", keepWorld_}};
}

CommandPtr ReparentNode::fromJson(const nlohmann::json& j) {
    return std::make_unique<ReparentNode>(j.at("node").get<NodeId>(), j.at("parent").get<NodeId>(),
                                          j.at("index").get<std::size_t>(), j.at("keepWorld").get<bool>());
}

} // namespace glint
