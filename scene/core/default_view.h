#pragma once
// A camera for scenes that have none, such as most downloaded glTF assets, so that they render
// without editing: from glTF's front (+Z) and about 19 degrees above, looking at the centre of
// worldBounds with +Y up, through Blender's default 39.6-degree lens, far enough back that the
// sphere around the bounds fits the narrower field of view with 10 % to spare (the editor's Frame
// All rule). A scene that draws nothing is looked at from 5 m away, the same way, at the origin.
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <string_view>

namespace glint {

inline constexpr std::string_view kDefaultViewName = "Default view";

// The unit vector from the centre of the scene to that camera: from the front (+Z), a little above.
glm::vec3 defaultViewFromCentre();

// The camera a render looks through when none is named: the active camera, else the first camera
// in node order; invalid when the scene has none.
NodeId defaultCamera(const Scene& scene);

// Adds that camera as a new root node for an image of `aspect` (width / height) and makes it the
// active camera. Returns its id.
NodeId addDefaultView(Scene& scene, float aspect);

} // namespace glint
