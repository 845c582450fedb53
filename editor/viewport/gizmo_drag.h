#pragma once
// One gizmo drag on one node: every mouse move pushes a SetTransform computed from the state at
// the press (never accumulated step by step, so no drift), all tagged with one History
// interaction, so the drag merges into a single undo step whose undo restores the exact start.
#include "editor/viewport/gizmo_math.h"
#include "scene/core/ids.h"

#include <cstdint>

namespace glint::editor {

class Document;

class GizmoDrag {
public:
    // Starts a drag when `ray` grabs a handle of `node`'s gizmo; otherwise active() is false.
    GizmoDrag(Document& document, NodeId node, const GizmoFrame& frame, GizmoMode mode, const bvh::Ray& ray);
    bool active() const { return axis_ >= 0; }
    int axis() const { return axis_; }
    void moveTo(const bvh::Ray& ray, const GizmoSnap& snap);
    void cancel(); // back to the start, still within the one undo step

private:
    void push(const Transform& local);

    Document& document_;
    NodeId node_;
    GizmoFrame frame_;
    GizmoMode mode_;
    bvh::Ray start_;
    int axis_ = -1;
    Transform startLocal_;
    glm::mat4 worldFromParent_{1.0f};
    std::uint64_t interaction_ = 0;
    bool moved_ = false;
};

} // namespace glint::editor
