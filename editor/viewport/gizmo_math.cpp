#include "editor/viewport/gizmo_math.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace glint::editor {

namespace {

constexpr double kHandleTolerance = 0.08; // of the gizmo size
constexpr double kRingTolerance = 0.1;

// Closest distance between the ray and the segment origin .. origin + axis * length.
double distanceToSegment(const bvh::Ray& ray, const glm::dvec3& origin, const glm::dvec3& axis, double length) {
    const auto s = closestOnAxis(ray, origin, axis);
    if (!s) return INFINITY;
    const double clamped = std::clamp(*s, 0.0, length);
    const glm::dvec3 p = origin + clamped * axis;
    const glm::dvec3 o(ray.origin);
    const glm::dvec3 d = glm::normalize(glm::dvec3(ray.direction));
    const double t = std::max(0.0, glm::dot(p - o, d));
    return glm::length(o + t * d - p);
}

} // namespace

double snapValue(double value, double step) { return step > 0.0 ? std::round(value / step) * step : value; }

std::optional<double> closestOnAxis(const bvh::Ray& ray, const glm::dvec3& origin, const glm::dvec3& axis) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(ray.direction));
    const glm::dvec3 w = glm::dvec3(ray.origin) - origin;
    const double b = glm::dot(axis, d);
    const double denom = 1.0 - b * b; // both unit
    if (denom < 1e-6) return std::nullopt;
    return (glm::dot(axis, w) - b * glm::dot(d, w)) / denom;
}

std::optional<glm::dvec3> intersectPlane(const bvh::Ray& ray, const glm::dvec3& origin, const glm::dvec3& normal) {
    const glm::dvec3 d(ray.direction);
    const double denom = glm::dot(normal, d);
    if (std::abs(denom) < 1e-9 * glm::length(d)) return std::nullopt;
    const double t = glm::dot(origin - glm::dvec3(ray.origin), normal) / denom;
    if (t <= 0.0) return std::nullopt;
    return glm::dvec3(ray.origin) + t * d;
}

std::optional<int> pickGizmoAxis(const bvh::Ray& ray, const GizmoFrame& frame, GizmoMode mode) {
    std::optional<int> best;
    double bestError = INFINITY;
    for (int a = 0; a < 3; ++a) {
        double error = INFINITY;
        if (mode == GizmoMode::Rotate) {
            if (const auto p = intersectPlane(ray, frame.origin, frame.axes[a]))
                error = std::abs(glm::length(*p - frame.origin) - frame.size) / (kRingTolerance * frame.size);
        } else {
            error = distanceToSegment(ray, frame.origin, frame.axes[a], frame.size) / (kHandleTolerance * frame.size);
        }
        if (error < 1.0 && error < bestError) {
            bestError = error;
            best = a;
        }
    }
    return best;
}

std::optional<double> dragAmount(GizmoMode mode, const GizmoFrame& frame, int axis, const bvh::Ray& start,
                                 const bvh::Ray& now, const GizmoSnap& snap) {
    const glm::dvec3 n = frame.axes[axis];
    if (mode == GizmoMode::Rotate) {
        const auto p0 = intersectPlane(start, frame.origin, n);
        const auto p1 = intersectPlane(now, frame.origin, n);
        if (!p0 || !p1) return std::nullopt;
        const glm::dvec3 a = *p0 - frame.origin, b = *p1 - frame.origin;
        const double angle = std::atan2(glm::dot(n, glm::cross(a, b)), glm::dot(a, b));
        const double step = snap.rotateStepDegrees * std::numbers::pi / 180.0;
        return snap.enabled ? snapValue(angle, step) : angle;
    }
    const auto s0 = closestOnAxis(start, frame.origin, n);
    const auto s1 = closestOnAxis(now, frame.origin, n);
    if (!s0 || !s1) return std::nullopt;
    if (mode == GizmoMode::Translate) {
        const double delta = *s1 - *s0;
        return snap.enabled ? snapValue(delta, snap.translateStep) : delta;
    }
    if (std::abs(*s0) < 1e-9) return std::nullopt;
    const double factor = *s1 / *s0;
    return snap.enabled ? snapValue(factor, snap.scaleStep) : factor;
}

Transform applyDrag(GizmoMode mode, const Transform& startLocal, const glm::mat4& worldFromParent,
                    const glm::dvec3& worldAxis, int axis, double amount) {
    Transform out = startLocal;
    const glm::dmat3 parentLinear(worldFromParent);
    switch (mode) {
    case GizmoMode::Translate: {
        const glm::dvec3 parentDelta = glm::inverse(parentLinear) * (worldAxis * amount);
        out.translation = glm::vec3(glm::dvec3(startLocal.translation) + parentDelta);
        break;
    }
    case GizmoMode::Rotate: {
        // The parent's rotation (scale removed), so the turn happens about the world axis.
        const glm::dquat parentRotation = glm::normalize(glm::quat_cast(glm::dmat3(
            glm::normalize(parentLinear[0]), glm::normalize(parentLinear[1]), glm::normalize(parentLinear[2]))));
        const glm::dquat turn = glm::angleAxis(amount, glm::normalize(worldAxis));
        const glm::dquat local = glm::inverse(parentRotation) * turn * parentRotation * glm::dquat(startLocal.rotation);
        out.rotation = glm::quat(glm::normalize(local));
        break;
    }
    case GizmoMode::Scale:
        out.scale[axis] = static_cast<float>(startLocal.scale[axis] * amount);
        break;
    }
    return out;
}

} // namespace glint::editor
