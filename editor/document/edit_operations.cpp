#include "edit_operations.h"

#include "scene/history/node_commands.h"
#include "scene/history/set_node_field.h"

#include <QCoreApplication>

#include <algorithm>
#include <exception>

namespace glint::editor {
namespace {


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

// Runs `body` inside one macro; a failure closes the macro and becomes a message.
template <class Body>
QString inMacro(Document& document, const QString& label, Body body) {
    document.beginMacro(label);
    try {
        body();
    } catch (const std::exception& e) {
        document.endMacro();
        return QString::fromStdString(e.what());
    }
    document.endMacro();
    return {};
}

} // namespace

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
    QString error = inMacro(document, QCoreApplication::translate("glint::editor::EditOperations", "Duplicate"), [&] {
        for (NodeId id : nodes) {
            auto command = std::make_unique<DuplicateNode>(id);
            DuplicateNode* raw = command.get();
            document.push(std::move(command));
            if (!raw->copyIds().empty()) copies.push_back(raw->copyIds().front());
        }
    });
    if (error.isEmpty()) document.setSelection(copies);
    return error;
}

QString addNode(Document& document, const QString& name, Component component) {
    Node node;
    node.name = name.toStdString();
    node.component = std::move(component);
    const NodeId current = document.currentNode();
    const Node* currentNode = document.scene().node(current);
    const NodeId parent = currentNode ? currentNode->parent : NodeId{};
    try {
        auto command = std::make_unique<AddNode>(std::move(node), parent);
        AddNode* raw = command.get();
        document.push(std::move(command));
        document.setSelection({raw->nodeId()});
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    return {};
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

Component defaultCamera() { return Camera{}; }

} // namespace glint::editor
