#include "editor/viewport/portal_travel.h"

#include "scene/core/portal.h"

#include <algorithm>

namespace glint::editor {

bool carryThroughPortal(ViewCamera& camera, const Scene& scene, const glm::dvec3& eyeBefore) {
    const glm::dvec3 eye = camera.position();
    if (eye == eyeBefore) return false;
    const auto crossing = firstPortalCrossing(scene, glm::vec3(eyeBefore), glm::vec3(eye));
    // t = 0: the move starts on the portal's plane, where the last crossing left it; going on out
    // of the exit must not carry it straight back.
    if (!crossing || !(crossing->t > 0.0f)) return false;
    const glm::dmat4 map(crossing->worldFromWorld);
    const glm::dvec3 target(map * glm::dvec4(camera.target, 1.0));
    const glm::dmat4 worldFromCamera = map * glm::dmat4(camera.worldFromCamera());
    const glm::dvec3 exitEye(worldFromCamera[3]);
    camera.distance = std::max(1e-3, glm::length(exitEye - target));
    setFromWorld(camera, glm::mat4(worldFromCamera), camera.yfov); // the angles
    camera.target = exitEye + camera.distance * camera.forward();   // the eye in double precision
    return true;
}

} // namespace glint::editor
