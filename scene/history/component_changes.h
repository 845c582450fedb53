#pragma once
// Which parts of the picture a node's component feeds, as a change set.
#include "change_set.h"
#include "scene/core/components.h"

namespace glint {

// Geometry for mesh instances and shapes (with the mesh or material they use), Light for
// lights, Camera for cameras; nothing for an empty component.
ChangeSet componentChange(NodeId node, const Component& component);

} // namespace glint
