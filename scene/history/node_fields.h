#pragma once
// The editable fields of a node, each described once for SetNodeField (set_node_field.h):
// how to read it, write it, what a change of it touches, and its name in logs and the UI.
#include "change_set.h"
#include "component_changes.h"
#include "scene/core/scene.h"

#include <string>

namespace glint {

struct NameField {
    using Value = std::string;
    static constexpr const char* type = "rename_node";
    static constexpr const char* label = "Rename";
    static const Value& get(const Node& node) { return node.name; }
    static void set(Scene& scene, NodeId id, const Value& value) { scene.setName(id, value); }
    static ChangeSet changes(NodeId id, const Value&, const Value&) { return nodeChange(Change::Name, id); }
};

struct TransformField {
    using Value = Transform;
    static constexpr const char* type = "set_transform";
    static constexpr const char* label = "Move";
    static const Value& get(const Node& node) { return node.local; }
    static void set(Scene& scene, NodeId id, const Value& value) { scene.setLocal(id, value); }
    static ChangeSet changes(NodeId id, const Value&, const Value&) { return nodeChange(Change::Transform, id); }
};

struct VisibilityField {
    using Value = bool;
    static constexpr const char* type = "set_visibility";
    static constexpr const char* label = "Show/hide";
    static const Value& get(const Node& node) { return node.visible; }
    static void set(Scene& scene, NodeId id, const Value& value) { scene.setVisible(id, value); }
    static ChangeSet changes(NodeId id, const Value&, const Value&) { return nodeChange(Change::Visibility, id); }
};

// Any light, camera, shape or mesh-instance property: the whole component, old and new.
struct ComponentField {
    using Value = Component;
    static constexpr const char* type = "set_component";
    static constexpr const char* label = "Edit component";
    static const Value& get(const Node& node) { return node.component; }
    static void set(Scene& scene, NodeId id, const Value& value) { scene.setComponent(id, value); }
    static ChangeSet changes(NodeId id, const Value& before, const Value& after) {
        ChangeSet changes = componentChange(id, before);
        changes.merge(componentChange(id, after));
        if (before.index() != after.index()) changes.add(Change::Structure);
        return changes;
    }
};

} // namespace glint
