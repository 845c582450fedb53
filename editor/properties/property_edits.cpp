#include "property_edits.h"

#include "editor/document/keyed_transform.h"
#include "editor/document/labelled_command.h"
#include "editor/history_view/command_labels.h"
#include "scene/history/asset_commands.h"
#include "scene/history/set_node_field.h"
#include "scene/history/settings_commands.h"

#include <QCoreApplication>

#include <algorithm>
#include <exception>

namespace glint::editor {
namespace {

// `label`: what the edit does, in the history's English ("Change exposure"); empty: the core's.
QString pushTagged(Document& document, CommandPtr command, std::uint64_t interaction, const std::string& label = {}) {
    command->interaction = interaction;
    if (!label.empty()) command = std::make_unique<LabelledCommand>(std::move(command), label);
    try {
        document.push(std::move(command));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

// The nodes a field edit of `node` applies to: every selected node of the same kind when `node`
// is one of several selected (as in Blender, a field changed there changes it on all of them).
std::vector<NodeId> editedNodes(const Document& document, NodeId node, bool sameComponent) {
    const Scene& scene = document.scene();
    const std::vector<NodeId>& selected = document.selection();
    if (selected.size() < 2 || std::find(selected.begin(), selected.end(), node) == selected.end()) return {node};
    std::vector<NodeId> out;
    for (const NodeId id : selected) {
        const Node* n = scene.node(id);
        if (n && (!sameComponent || n->component.index() == scene.at(node).component.index())) out.push_back(id);
    }
    return out;
}

// Pushes `edit(id)` for each node, as one undo step when there are several.
QString editEach(Document& document, const std::vector<NodeId>& nodes, const std::function<QString(NodeId)>& edit) {
    if (nodes.size() == 1) return edit(nodes.front());
    document.beginMacro(QCoreApplication::translate("glint::editor::PropertyEdits", "Edit %1 nodes").arg(nodes.size()));
    QString error;
    for (const NodeId id : nodes)
        if (error.isEmpty()) error = edit(id);
    document.endMacro();
    return error;
}

} // namespace

QString editTransform(Document& document, NodeId node, const std::function<void(Transform&)>& change,
                      std::uint64_t interaction) {
    if (!document.scene().node(node)) return {};
    return editEach(document, editedNodes(document, node, false), [&](NodeId id) {
        const Transform shown = shownTransform(document, id);
        Transform t = shown;
        change(t);
        if (t == shown) return QString();
        return pushTransform(document, id, t, interaction);
    });
}

QString editComponent(Document& document, NodeId node, const std::function<void(Component&)>& change,
                      std::uint64_t interaction) {
    if (!document.scene().node(node)) return {};
    return editEach(document, editedNodes(document, node, true), [&](NodeId id) {
        const Node& n = document.scene().at(id);
        Component c = n.component;
        change(c);
        if (c == n.component) return QString();
        const std::string label = describeComponentEdit(n.component, c);
        return pushTagged(document, std::make_unique<SetComponent>(id, std::move(c)), interaction, label);
    });
}

QString editMaterial(Document& document, MaterialId material, const std::function<void(Material&)>& change,
                     std::uint64_t interaction) {
    const Material* m = document.scene().materials.find(material);
    if (!m) return {};
    Material copy = *m;
    change(copy);
    if (copy == *m) return {};
    const std::string label = describeMaterialEdit(*m, copy);
    return pushTagged(document, std::make_unique<SetMaterial>(material, std::move(copy)), interaction, label);
}

QString editSettings(Document& document, const std::function<void(ProjectSettings&)>& change,
                     std::uint64_t interaction) {
    ProjectSettings s = document.scene().settings;
    change(s);
    if (s == document.scene().settings) return {};
    const std::string label = describeSettingsEdit(document.scene().settings, s);
    return pushTagged(document, std::make_unique<SetProjectSettings>(std::move(s)), interaction, label);
}

MaterialId materialOf(const Scene& scene, NodeId node) {
    const Node* n = scene.node(node);
    if (!n) return {};
    if (const auto* shape = n->get<Shape>()) return shape->material;
    if (const auto* instance = n->get<MeshInstance>()) {
        const Mesh* mesh = scene.meshes.find(instance->mesh);
        if (mesh && !mesh->primitives.empty()) return mesh->primitives.front().material;
    }
    return {};
}

} // namespace glint::editor
