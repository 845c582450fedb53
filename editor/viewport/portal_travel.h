#pragma once
// The view camera passing through a linked portal (scene/core/portal.h): when a move carries its
// eye across a portal's rectangle, the whole view (eye, direction and orbit target) is taken
// through the pair's map, so it comes out of the partner as a ray would. Pure math, no Qt.
#include "editor/viewport/view_camera.h"

#include "scene/core/scene.h"

namespace glint::editor {

// Call after a move (fly, orbit, pan, zoom) with the eye from before it. Returns whether the
// eye crossed a linked portal and the view was carried through. One portal per move: what is
// left of a long step past the exit is not tested again. The view keeps +Y up (setFromWorld), so
// a pair that tilts the map drops its roll; the orbit distance follows the pair's scale.
bool carryThroughPortal(ViewCamera& camera, const Scene& scene, const glm::dvec3& eyeBefore);

} // namespace glint::editor
