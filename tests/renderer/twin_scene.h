#pragma once
// A scene's mesh instances flattened for the CPU twin's traversal (renderer/bvh/traverse.h), as the
// renderer flattens them, with each instance's node name and transform: for the benchmark programs
// that walk the twin.
#include "renderer/bvh/flat_scene.h"
#include "renderer/bvh/ray.h"
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace glint::test {

struct TwinScene {
    bvh::FlatScene flat;
    std::vector<std::string> names;   // per instance
    std::vector<glm::mat4> worldFrom; // per instance
};

TwinScene twinScene(const Scene& scene);

// The world-space unit geometric normal of a triangle hit (the winding's front, not faced to the ray).
glm::vec3 hitNormal(const TwinScene& twin, const bvh::RayHit& hit);

} // namespace glint::test
