#pragma once
// The world-space box around what a scene draws, for framing a view of it.
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <limits>

namespace glint {

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::infinity()};
    glm::vec3 max{-std::numeric_limits<float>::infinity()};

    bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    void grow(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    glm::vec3 centre() const { return 0.5f * (min + max); }
};

// Every visible mesh and finite shape, each as its local box's eight corners carried into the
// world (a box around the boxes: exact for unrotated nodes). Ground planes are infinite and
// lights and cameras draw nothing, so they are left out; non-finite positions are skipped.
// Empty when nothing is left.
Bounds worldBounds(const Scene& scene);

} // namespace glint
