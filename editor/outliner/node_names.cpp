#include "node_names.h"

#include <QCoreApplication>

namespace glint::editor {
namespace {

QString translated(const char* text) { return QCoreApplication::translate("glint::editor::NodeNames", text); }

QString shapeName(ShapeKind kind) {
    switch (kind) {
    case ShapeKind::Sphere: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Sphere %1"));
    case ShapeKind::Quad: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Quad %1"));
    case ShapeKind::Disk: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Disk %1"));
    case ShapeKind::Box: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Box %1"));
    case ShapeKind::Cylinder: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Cylinder %1"));
    case ShapeKind::GroundPlane: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Ground plane %1"));
    }
    return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Node %1"));
}

QString lightName(LightType type) {
    switch (type) {
    case LightType::Sun: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Sun %1"));
    case LightType::Point: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Point light %1"));
    case LightType::Spot: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Spot light %1"));
    case LightType::Area: return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Area light %1"));
    }
    return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Node %1"));
}

} // namespace

bool hasOwnName(const Scene& scene, NodeId id) {
    const Node* node = scene.node(id);
    return node && !node->name.empty();
}

QString nodeDisplayName(const Scene& scene, NodeId id) {
    const Node* node = scene.node(id);
    if (!node) return {};
    if (!node->name.empty()) return QString::fromStdString(node->name);
    if (const auto* instance = node->get<MeshInstance>()) {
        const Mesh* mesh = scene.meshes.find(instance->mesh);
        if (mesh && !mesh->name.empty()) return QString::fromStdString(mesh->name);
        return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Mesh %1")).arg(id.value);
    }
    if (node->get<Camera>()) return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Camera %1")).arg(id.value);
    if (const auto* light = node->get<Light>()) return lightName(light->type).arg(id.value);
    if (const auto* shape = node->get<Shape>()) return shapeName(shape->kind).arg(id.value);
    return translated(QT_TRANSLATE_NOOP("glint::editor::NodeNames", "Node %1")).arg(id.value);
}

} // namespace glint::editor
