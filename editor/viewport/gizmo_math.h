#pragma once
// Translate / rotate / scale gizmo math: which handle a ray grabs, and how far a drag from one
// ray to another moves, turns or scales along it, with optional snapping. Pure math in world
// space (no Qt, no GL); the viewport turns the result into one SetTransform per mouse move,
// all tagged with one History interaction so that the drag is one undo step.
#include "renderer/bvh/ray.h"
#include "scene/core/transform.h"

#include <glm/glm.hpp>

#include <optional>

namespace glint::editor {

// Whether the move and rotate handles follow the world's axes or the node's own (scale handles are
// always the node's).
enum class GizmoSpace { World, Local };

enum class GizmoMode { Translate, Rotate, Scale };

struct GizmoSnap {
    bool enabled = false;
    double translateStep = 0.1;  // metres
    double rotateStepDegrees = 15.0;
    double scaleStep = 0.1;      // in scale factor
};

// The gizmo at a node: its origin and world axes (unit), and its size in metres on screen.
struct GizmoFrame {
    glm::dvec3 origin{0.0};
    glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double size = 1.0;
};

double snapValue(double value, double step);

// Parameter s of the point origin + s * axis closest to the ray (axis unit). Empty when the ray
// runs (nearly) parallel to the axis, where the drag would be unstable.
std::optional<double> closestOnAxis(const bvh::Ray& ray, const glm::dvec3& origin, const glm::dvec3& axis);
// Where the ray meets the plane through `origin` with `normal`; empty when parallel or behind.
std::optional<glm::dvec3> intersectPlane(const bvh::Ray& ray, const glm::dvec3& origin, const glm::dvec3& normal);

// The handle (axis 0..2) a ray grabs, if any: translate/scale by the distance from the axis
// segments, rotate by the rings of radius `size` about each axis.
std::optional<int> pickGizmoAxis(const bvh::Ray& ray, const GizmoFrame& frame, GizmoMode mode);

// The drag from `start` to `now` on handle `axis`:
// metres along the axis (translate), radians about it (rotate, right-handed), factor (scale).
std::optional<double> dragAmount(GizmoMode mode, const GizmoFrame& frame, int axis, const bvh::Ray& start,
                                 const bvh::Ray& now, const GizmoSnap& snap);

// The node's new local transform after a drag, from its local transform when the drag began and
// its parent's world matrix. Translation and rotation follow the gizmo's world axis; scale is
// along the node's own axis `axis`.
Transform applyDrag(GizmoMode mode, const Transform& startLocal, const glm::mat4& worldFromParent,
                    const glm::dvec3& worldAxis, int axis, double amount);

} // namespace glint::editor
