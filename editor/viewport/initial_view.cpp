#include "editor/viewport/initial_view.h"

#include "scene/anim/scene_at_time.h"
#include "scene/core/default_view.h"
#include "scene/core/scene_bounds.h"

#include <cmath>

namespace glint::editor {
namespace {

constexpr double kEmptySceneDistance = 5.0;

// Orbit about the scene's centre where the camera looks towards it, else about its focus point.
double orbitDistance(const glm::dmat4& worldFromCamera, const Bounds& bounds, float focusDistance) {
    if (!bounds.empty()) {
        const glm::dvec3 eye(worldFromCamera[3]);
        const glm::dvec3 forward = -glm::normalize(glm::dvec3(worldFromCamera[2]));
        const double depth = glm::dot(glm::dvec3(bounds.centre()) - eye, forward);
        if (depth > 1e-3) return depth;
    }
    return std::isfinite(focusDistance) && focusDistance > 0.0f ? double(focusDistance) : kEmptySceneDistance;
}

} // namespace

ViewCamera initialView(const Scene& scene, double aspect) {
    Scene storage;
    const Scene& posed = posedAt(scene, 0.0, storage);
    const Bounds bounds = worldBounds(posed);
    ViewCamera view;
    if (const NodeId id = defaultCamera(posed); id.valid()) {
        const Camera& lens = *posed.at(id).get<Camera>();
        const glm::mat4 worldFromCamera = posed.worldFromNode(id);
        view.distance = orbitDistance(glm::dmat4(worldFromCamera), bounds, lens.focusDistance);
        // The viewport is perspective: an orthographic camera gives its place, not its lens.
        setFromWorld(view, worldFromCamera, lens.projection == Projection::Perspective ? lens.yfov : view.yfov);
        return view;
    }
    const glm::dvec3 fromCentre(defaultViewFromCentre());
    view.pitch = std::asin(fromCentre.y);
    view.yaw = std::atan2(fromCentre.x, fromCentre.z);
    if (bounds.empty()) {
        view.distance = kEmptySceneDistance;
        return view;
    }
    const double radius = 0.5 * glm::length(glm::dvec3(bounds.max - bounds.min));
    frameSphere(view, glm::dvec3(bounds.centre()), radius, aspect);
    return view;
}

} // namespace glint::editor
