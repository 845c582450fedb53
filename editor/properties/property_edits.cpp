#include "property_edits.h"

#include "scene/history/asset_commands.h"
#include "scene/history/set_node_field.h"
#include "scene/history/settings_commands.h"

#include <exception>

namespace glint::editor {
namespace {

QString pushTagged(Document& document, CommandPtr command, std::uint64_t interaction) {
    command->interaction = interaction;
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
    return pushTagged(document, std::make_unique<SetComponent>(node, std::move(c)), interaction);
}

QString editMaterial(Document& document, MaterialId material, const std::function<void(Material&)>& change,
                     std::uint64_t interaction) {
    const Material* m = document.scene().materials.find(material);
    if (!m) return {};
    Material copy = *m;
    change(copy);
    if (copy == *m) return {};
    return pushTagged(document, std::make_unique<SetMaterial>(material, std::move(copy)), interaction);
}

QString editSettings(Document& document, const std::function<void(ProjectSettings&)>& change,
                     std::uint64_t interaction) {
    ProjectSettings s = document.scene().settings;
    change(s);
    if (s == document.scene().settings) return {};
    return pushTagged(document, std::make_unique<SetProjectSettings>(std::move(s)), interaction);
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
