#include "edit_operations.h"
#include "editor/document/in_macro.h"
#include "editor/document/portal_edits.h"

#include "scene/history/asset_commands.h"
#include "scene/history/node_commands.h"
#include "scene/history/set_node_field.h"

#include <QCoreApplication>

#include <algorithm>
#include <map>
#include <set>
#include <cstdio>
#include <exception>

namespace glint::editor {
namespace {

// A name no material of the scene has: `base`, else `base.001`, `base.002`, ... as Blender names copies.
std::string uniqueMaterialName(const Scene& scene, const std::string& base) {
    const auto taken = [&](const std::string& name) {
        for (const auto& [id, material] : scene.materials)
            if (material.name == name) return true;
        return false;
    };
    if (!taken(base)) return base;
    for (int i = 1;; ++i) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", i);
        if (!taken(base + suffix)) return base + suffix;
    }
}

// The name Blender gives a copy: the original's without a ".NNN" suffix, then the first ".001",
// ".002", ... that no node has ("Sphere" -> "Sphere.001", "Sphere.001" -> "Sphere.002").
std::string copyName(const std::string& name, const std::set<std::string>& taken) {
    std::string base = name;
    const std::size_t dot = name.rfind('.');
    if (dot != std::string::npos && name.size() - dot - 1 >= 3 &&
        std::all_of(name.begin() + static_cast<std::ptrdiff_t>(dot) + 1, name.end(), [](char c) { return c >= '0' && c <= '9'; }))
        base = name.substr(0, dot);
    for (int i = 1;; ++i) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", i);
        if (!taken.count(base + suffix)) return base + suffix;
    }
}

// The selected nodes that are not inside another selected node, in scene order.
std::vector<NodeId> topLevelSelection(const Document& document) {
    const Scene& scene = document.scene();
    std::vector<NodeId> out;
    for (NodeId id : scene.depthFirst()) {
        if (!document.isSelected(id)) continue;
        const bool inside = std::any_of(out.begin(), out.end(), [&](NodeId a) { return scene.isAncestor(a, id); });
        if (!inside) out.push_back(id);
    }
    return out;
}

} // namespace

// A new shape's own material: glTF's defaults but a mid-grey dielectric (glTF's default material
// is a white metal, which renders as a mirror), so it shows the light and can be edited at once.
Material newShapeMaterial(const Scene& scene) {
    Material m;
    m.name = uniqueMaterialName(scene, "Material");
    m.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.5f;
    return m;
}

QString deleteSelection(Document& document) {
    const std::vector<NodeId> nodes = topLevelSelection(document);
    if (nodes.empty()) return QCoreApplication::translate("glint::editor::EditOperations", "Nothing is selected.");
    return inMacro(document, QCoreApplication::translate("glint::editor::EditOperations", "Delete"), [&] {
        for (NodeId id : nodes) document.push(std::make_unique<RemoveNode>(id));
    });
}

QString duplicateSelection(Document& document) {
    const std::vector<NodeId> nodes = topLevelSelection(document);
    if (nodes.empty()) return QCoreApplication::translate("glint::editor::EditOperations", "Nothing is selected.");
    std::vector<NodeId> copies;
    std::set<std::string> taken;
    for (const NodeId id : document.scene().depthFirst()) taken.insert(document.scene().at(id).name);
    std::map<NodeId, NodeId> copyOf;
    QString error = inMacro(document, QCoreApplication::translate("glint::editor::EditOperations", "Duplicate"), [&] {
        for (NodeId id : nodes) {
            const std::vector<NodeId> originals = document.scene().subtree(id);
            auto command = std::make_unique<DuplicateNode>(id);
            DuplicateNode* raw = command.get();
            document.push(std::move(command));
            if (!raw->copyIds().empty()) copies.push_back(raw->copyIds().front());
            for (std::size_t i = 0; i < originals.size() && i < raw->copyIds().size(); ++i) copyOf[originals[i]] = raw->copyIds()[i];
            // Each copy gets a name of its own, as in Blender (an unnamed node stays unnamed).
            for (const NodeId copy : raw->copyIds()) {
                const std::string& name = document.scene().at(copy).name;
                if (name.empty()) continue;
                const std::string unique = copyName(name, taken);
                taken.insert(unique);
                document.push(std::make_unique<RenameNode>(copy, unique));
            }
        }
        relinkCopiedPortals(document, copyOf);
    });
    if (error.isEmpty()) document.setSelection(copies);
    return error;
}

QString addNode(Document& document, const QString& name, Component component) {
    const Scene& scene = document.scene();
    const Node* currentNode = scene.node(document.currentNode());
    const NodeId parent = currentNode ? currentNode->parent : NodeId{};
    Placement placed = placeNewNode(component, document.viewFocus());
    Node node;
    node.name = name.toStdString();
    node.local = placed.worldFromNode;
    if (parent.valid()) node.local = fromMatrix(glm::inverse(scene.worldFromNode(parent)) * toMatrix(placed.worldFromNode));
    NodeId added;
    const QString error = inMacro(document, QCoreApplication::translate("glint::editor::EditOperations", "Add %1").arg(name), [&] {
        if (auto* shape = std::get_if<Shape>(&placed.component)) {
            auto material = std::make_unique<AddAsset<Material>>(newShapeMaterial(scene));
            AddAsset<Material>* raw = material.get();
            document.push(std::move(material));
            shape->material = raw->id();
        }
        node.component = std::move(placed.component);
        auto command = std::make_unique<AddNode>(std::move(node), parent);
        AddNode* raw = command.get();
        document.push(std::move(command));
        added = raw->nodeId();
    });
    if (error.isEmpty()) document.setSelection({added});
    return error;
}

QString renameNode(Document& document, NodeId id, const QString& name) {
    const Node* node = document.scene().node(id);
    if (!node) return QCoreApplication::translate("glint::editor::EditOperations", "The node no longer exists.");
    if (node->name == name.toStdString()) return {};
    try {
        document.push(std::make_unique<RenameNode>(id, name.toStdString()));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

QString reparentNodes(Document& document, const std::vector<NodeId>& nodes, NodeId parent, std::size_t index) {
    const Scene& scene = document.scene();
    for (NodeId id : nodes)
        if (id == parent || (parent && scene.isAncestor(id, parent)))
            return QCoreApplication::translate("glint::editor::EditOperations", "A node cannot be moved into itself or its own children.");
    QString error = inMacro(document, QCoreApplication::translate("glint::editor::EditOperations", "Reparent"), [&] {
        std::size_t at = index;
        for (NodeId id : nodes) {
            document.push(std::make_unique<ReparentNode>(id, parent, at, true));
            if (at != SIZE_MAX) at = document.scene().indexInParent(id) + 1;
        }
    });
    if (error.isEmpty()) document.setSelection(nodes);
    return error;
}

QString setVisible(Document& document, NodeId id, bool visible) {
    const Node* node = document.scene().node(id);
    if (!node) return QCoreApplication::translate("glint::editor::EditOperations", "The node no longer exists.");
    if (node->visible == visible) return {};
    try {
        document.push(std::make_unique<SetVisibility>(id, visible));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

Component defaultShape(ShapeKind kind) {
    Shape shape;
    shape.kind = kind;
    if (kind == ShapeKind::Quad) shape.size = {2.0f, 1.0f, 2.0f};
    return shape;
}

Component defaultLight(LightType type) {
    Light light;
    light.type = type;
    light.intensity = type == LightType::Sun ? 3.0f : 50.0f;
    return light;
}

// Sized for 1 m like the shapes (node_placement.h scales it and sets its power): a 1 m square or
// disk, or a sphere of radius 0.1 m (Blender's default light radius), facing down once placed.
Component defaultAreaLight(AreaShape shape) {
    Light light;
    light.type = LightType::Area;
    light.areaShape = shape;
    light.size = {1.0f, 1.0f};
    light.radius = shape == AreaShape::Sphere ? 0.1f : 0.0f;
    light.intensity = 10.0f;
    return light;
}

Component defaultCamera() { return Camera{}; }

} // namespace glint::editor
