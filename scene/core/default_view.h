#pragma once
// A camera for scenes that have none, such as most downloaded glTF assets, so that they render
// without editing: glTF's front view (from +Z, looking along -Z, +Y up) through Blender's default
// 39.6-degree lens, far enough back that the sphere around worldBounds fits the narrower field of
// view with 10 % to spare (the editor's Frame All rule). A scene that draws nothing is looked at
// from 5 m in front of the origin.
#include "scene/core/scene.h"

#include <string_view>

namespace glint {

inline constexpr std::string_view kDefaultViewName = "Default view";

// Adds that camera as a new root node for an image of `aspect` (width / height) and makes it the
// active camera. Returns its id.
NodeId addDefaultView(Scene& scene, float aspect);

} // namespace glint
