#pragma once
// Whether a node is drawn: it and every ancestor are visible.
#include "scene/core/scene.h"

namespace glint {

inline bool visibleInWorld(const Scene& scene, const Node& node) { return scene.visibleInWorld(node.id); }

} // namespace glint
