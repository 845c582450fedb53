#include "component_changes.h"

#include <variant>

namespace glint {

ChangeSet componentChange(NodeId node, const Component& component) {
    ChangeSet changes;
    changes.nodes.insert(node);
    if (const auto* instance = std::get_if<MeshInstance>(&component)) {
        changes.add(Change::Geometry);
        if (instance->mesh) changes.meshes.insert(instance->mesh);
    } else if (const auto* shape = std::get_if<Shape>(&component)) {
        changes.add(Change::Geometry);
        if (shape->material) changes.materials.insert(shape->material);
    } else if (std::holds_alternative<Light>(component)) {
        changes.add(Change::Light);
    } else if (std::holds_alternative<Camera>(component)) {
        changes.add(Change::Camera);
    }
    return changes;
}

} // namespace glint
