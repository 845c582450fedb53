#include "property_edits.h"

#include "editor/document/labelled_command.h"
#include "editor/history_view/command_labels.h"
#include "scene/history/asset_commands.h"
#include "scene/history/set_node_field.h"
#include "scene/history/settings_commands.h"

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

} // namespace

QString editTransform(Document& document, NodeId node, const std::function<void(Transform&)>& change,
                      std::uint64_t interaction) {
    const Node* n = document.scene().node(node);
    if (!n) return {};
    Transform t = n->local;
    change(t);
    if (t == n->local) return {};
    return pushTagged(document, std::make_unique<SetTransform>(node, t), interaction);
}

QString editComponent(Document& document, NodeId node, const std::function<void(Component&)>& change,
                      std::uint64_t interaction) {
    const Node* n = document.scene().node(node);
    if (!n) return {};
    Component c = n->component;
    change(c);
    if (c == n->component) return {};
    const std::string label = describeComponentEdit(n->component, c);
    return pushTagged(document, std::make_unique<SetComponent>(node, std::move(c)), interaction, label);
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
