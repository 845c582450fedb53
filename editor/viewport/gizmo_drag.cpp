#include "editor/viewport/gizmo_drag.h"

#include "editor/document/document.h"
#include "editor/document/keyed_transform.h"
#include "scene/anim/scene_at_time.h"

namespace glint::editor {

GizmoDrag::GizmoDrag(Document& document, NodeId node, const GizmoFrame& frame, GizmoMode mode, const bvh::Ray& ray)
    : document_(document), node_(node), frame_(frame), mode_(mode), start_(ray) {
    const Scene& scene = document.scene();
    if (!scene.contains(node)) return;
    const auto axis = pickGizmoAxis(ray, frame, mode);
    if (!axis) return;
    axis_ = *axis;
    // From the pose shown at the current time (a keyed node's keys decide it, not its stored TRS).
    Scene storage;
    const Scene& posed = posedAt(scene, document.currentTime(), storage);
    startLocal_ = shownTransform(document, node);
    if (const NodeId parent = scene.at(node).parent; parent.valid()) worldFromParent_ = posed.worldFromNode(parent);
    interaction_ = document.beginInteraction();
}

void GizmoDrag::moveTo(const bvh::Ray& ray, const GizmoSnap& snap) {
    if (!active()) return;
    const auto amount = dragAmount(mode_, frame_, axis_, start_, ray, snap);
    if (!amount) return;
    push(applyDrag(mode_, startLocal_, worldFromParent_, frame_.axes[axis_], axis_, *amount));
}

// Takes the drag's step back whole: pushing the start pose again would leave a key that the drag
// made on a keyed node, and a redo step for an edit the user cancelled.
void GizmoDrag::cancel() {
    if (active() && moved_) document_.revertInteraction(interaction_);
    moved_ = false;
}

void GizmoDrag::push(const Transform& local) {
    if (!document_.scene().contains(node_) || shownTransform(document_, node_) == local) return;
    if (pushTransform(document_, node_, local, interaction_).isEmpty()) moved_ = true;
}

} // namespace glint::editor
