#pragma once
// Where the viewport looks when a file is opened or a new scene starts: through the camera a
// render would use (the active camera, else the first), orbiting about the depth of the scene's
// centre; a scene without a camera is framed whole from the direction of the CLI's default view
// (front, a little above), as Frame All would; an empty scene is seen from 5 m at the origin.
// Pure math on the scene at time 0, no Qt.
#include "editor/viewport/view_camera.h"
#include "scene/core/scene.h"

namespace glint::editor {

// `aspect`: the view's width / height.
ViewCamera initialView(const Scene& scene, double aspect);

} // namespace glint::editor
