#pragma once
// Whether a node is drawn: it and every ancestor are visible.
#include "scene/core/scene.h"

namespace glint {

inline bool visibleInWorld(const Scene& scene, const Node& node) {
    for (const Node* n = &node; n; n = n->parent ? scene.node(n->parent) : nullptr)
        if (!n->visible) return false;
    return true;
}

} // namespace glint
