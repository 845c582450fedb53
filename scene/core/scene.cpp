#include "scene.h"

#include <algorithm>
#include <stdexcept>

namespace glint {

const Node* Scene::node(NodeId id) const {
    auto it = nodes_.find(id);
    return it == nodes_.end() ? nullptr : &it->second;
}

const Node& Scene::at(NodeId id) const {
    auto it = nodes_.find(id);
    if (it == nodes_.end()) throw std::out_of_range("Scene: no node " + std::to_string(id.value));
    return it->second;
}

Node& Scene::mutableNode(NodeId id) {
    auto it = nodes_.find(id);
    if (it == nodes_.end()) throw std::out_of_range("Scene: no node " + std::to_string(id.value));
    return it->second;
}

void Scene::detach(Node& n) {
    auto& siblings = n.parent ? mutableNode(n.parent).children : roots_;
    siblings.erase(std::remove(siblings.begin(), siblings.end(), n.id), siblings.end());
    n.parent = {};
}

void Scene::attach(Node& n, NodeId parent, std::size_t index) {
    auto& siblings = parent ? mutableNode(parent).children : roots_;
    index = std::min(index, siblings.size());
    siblings.insert(siblings.begin() + static_cast<std::ptrdiff_t>(index), n.id);
    n.parent = parent;
}

NodeId Scene::addNode(Node node, NodeId parent, std::size_t index) {
    if (parent && !contains(parent)) throw std::invalid_argument("Scene::addNode: no parent " + std::to_string(parent.value));
    if (!node.id) node.id = NodeId{nextNodeId_};
    if (contains(node.id)) throw std::invalid_argument("Scene::addNode: id taken " + std::to_string(node.id.value));
    nextNodeId_ = std::max(nextNodeId_, node.id.value + 1);
    node.parent = {};
    node.children.clear();
    NodeId id = node.id;
    Node& stored = nodes_.emplace(id, std::move(node)).first->second;
    attach(stored, parent, index);
    return id;
}

Node Scene::removeLeaf(NodeId id) {
    Node& n = mutableNode(id);
    if (!n.children.empty()) throw std::invalid_argument("Scene::removeLeaf: node has children");
    NodeId parent = n.parent;
    invalidateCaches(id);
    detach(n);
    Node removed = std::move(n);
    nodes_.erase(id);
    removed.parent = parent;
    return removed;
}

void Scene::setParent(NodeId id, NodeId parent, std::size_t index) {
    if (parent == id || (parent && isAncestor(id, parent)))
        throw std::invalid_argument("Scene::setParent: would create a cycle");
    if (parent && !contains(parent)) throw std::invalid_argument("Scene::setParent: no parent");
    Node& n = mutableNode(id);
    invalidateCaches(id);
    detach(n);
    attach(n, parent, index);
}

std::size_t Scene::indexInParent(NodeId id) const {
    const Node& n = at(id);
    const auto& siblings = n.parent ? at(n.parent).children : roots_;
    return static_cast<std::size_t>(std::find(siblings.begin(), siblings.end(), id) - siblings.begin());
}

void Scene::setLocal(NodeId id, const Transform& local) {
    mutableNode(id).local = local;
    invalidateCaches(id);
}

void Scene::setName(NodeId id, std::string name) { mutableNode(id).name = std::move(name); }
void Scene::setVisible(NodeId id, bool visible) {
    mutableNode(id).visible = visible;
    invalidateCaches(id);
}
void Scene::setComponent(NodeId id, Component component) { mutableNode(id).component = std::move(component); }
void Scene::setUnknown(NodeId id, nlohmann::json unknown) { mutableNode(id).unknown = std::move(unknown); }
Component& Scene::component(NodeId id) { return mutableNode(id).component; }

void Scene::invalidateCaches(NodeId id) const {
    if (worldCache_.empty() && visibleCache_.empty()) return;
    for (NodeId n : subtree(id)) {
        worldCache_.erase(n);
        visibleCache_.erase(n);
    }
}

// Walks up to the first node with a cached answer (or past the root), then answers down that walk.
template <class Value, class Step>
Value Scene::cachedDownTheHierarchy(NodeId id, std::map<NodeId, Value>& cache, Value rootValue, Step step) const {
    std::vector<const Node*> walk;
    Value value = rootValue;
    for (NodeId up = id; up;) {
        if (auto it = cache.find(up); it != cache.end()) {
            value = it->second;
            break;
        }
        walk.push_back(&at(up));
        up = walk.back()->parent;
    }
    for (auto it = walk.rbegin(); it != walk.rend(); ++it) {
        value = step(value, **it);
        cache[(*it)->id] = value;
    }
    return value;
}

glm::mat4 Scene::worldFromNode(NodeId id) const {
    return cachedDownTheHierarchy(id, worldCache_, glm::mat4(1.0f),
                                  [](const glm::mat4& parentWorld, const Node& n) { return parentWorld * toMatrix(n.local); });
}

bool Scene::visibleInWorld(NodeId id) const {
    return cachedDownTheHierarchy(id, visibleCache_, true, [](bool parentVisible, const Node& n) { return parentVisible && n.visible; });
}

bool Scene::isAncestor(NodeId ancestor, NodeId id) const {
    // Bounded by the node count, so a corrupted hierarchy cannot loop forever.
    const Node* n = node(id);
    for (std::size_t steps = 0; n && n->parent && steps <= nodes_.size(); ++steps) {
        if (n->parent == ancestor) return true;
        n = node(n->parent);
    }
    return false;
}

std::vector<NodeId> Scene::subtree(NodeId id) const {
    std::vector<NodeId> out;
    std::vector<NodeId> stack{id};
    while (!stack.empty()) {
        NodeId cur = stack.back();
        stack.pop_back();
        const Node* n = node(cur);
        if (!n) continue;
        out.push_back(cur);
        for (auto it = n->children.rbegin(); it != n->children.rend(); ++it) stack.push_back(*it);
    }
    return out;
}

std::vector<NodeId> Scene::depthFirst() const {
    std::vector<NodeId> out;
    out.reserve(nodes_.size());
    for (NodeId root : roots_) {
        auto sub = subtree(root);
        out.insert(out.end(), sub.begin(), sub.end());
    }
    return out;
}

std::optional<NodeId> Scene::findByName(const std::string& wanted) const {
    for (NodeId id : depthFirst())
        if (at(id).name == wanted) return id;
    return std::nullopt;
}

bool operator==(const Scene& a, const Scene& b) {
    return a.nodes_ == b.nodes_ && a.roots_ == b.roots_ && a.meshes == b.meshes && a.materials == b.materials &&
           a.textures == b.textures && a.images == b.images && a.samplers == b.samplers &&
           a.animations == b.animations && a.name == b.name && a.settings == b.settings && a.unknown == b.unknown;
}

} // namespace glint
