#include "editor/viewport/gizmo_drag.h"

#include "editor/document/document.h"
#include "scene/history/set_node_field.h"

#include <memory>

namespace glint::editor {

GizmoDrag::GizmoDrag(Document& document, NodeId node, const GizmoFrame& frame, GizmoMode mode, const bvh::Ray& ray)
    : document_(document), node_(node), frame_(frame), mode_(mode), start_(ray) {
    const Scene& scene = document.scene();
    if (!scene.contains(node)) return;
    const auto axis = pickGizmoAxis(ray, frame, mode);
    if (!axis) return;
    axis_ = *axis;
    const Node& n = scene.at(node);
    startLocal_ = n.local;
    if (n.parent.valid()) worldFromParent_ = scene.worldFromNode(n.parent);
    interaction_ = document.beginInteraction();
}

void GizmoDrag::moveTo(const bvh::Ray& ray, const GizmoSnap& snap) {
    if (!active()) return;
    const auto amount = dragAmount(mode_, frame_, axis_, start_, ray, snap);
    if (!amount) return;
    push(applyDrag(mode_, startLocal_, worldFromParent_, frame_.axes[axis_], axis_, *amount));
}

void GizmoDrag::cancel() {
    if (active() && moved_) push(startLocal_);
}

void GizmoDrag::push(const Transform& local) {
    if (!document_.scene().contains(node_) || document_.scene().at(node_).local == local) return;
    auto command = std::make_unique<SetTransform>(node_, local);
    command->interaction = interaction_;
    document_.push(std::move(command));
    moved_ = true;
}

} // namespace glint::editor
