#pragma once
// The camera a render looks through, resolved from the scene: by name (the glTF node's name,
// docs/CLI.md --camera), else the project's active camera, else the first camera in node order.
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <string>

namespace glint::renderer {

struct CameraSetup {
    glm::mat4 worldFromCamera{1.0f}; // camera looks along its -Z, +Y up (glTF)
    bool orthographic = false;
    glm::vec2 halfExtent{1.0f};      // tan(fov/2) per axis, or orthographic half extents in metres
    float lensRadius = 0.0f;
    float focusDistance = 1.0f;
    float exposure = 0.0f;           // the camera's own EV
    NodeId node{};
};

// Throws std::runtime_error when `name` names no camera, or the scene has none.
CameraSetup resolveCamera(const Scene& scene, const std::string& name, int width, int height);

} // namespace glint::renderer
