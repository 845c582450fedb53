#pragma once
#include <glm/glm.hpp>

#include <cstdint>

namespace glint::bvh {

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, 1.0f}; // any length; t is measured in its units
};

// A closest hit. instance < 0: no hit.
struct RayHit {
    float t = 0.0f;
    float u = 0.0f; // barycentric weight of vertex 1
    float v = 0.0f; // barycentric weight of vertex 2
    std::int32_t instance = -1;
    std::int32_t slot = -1;     // triangle slot (FlatScene), -1 for a shape instance
    std::int32_t triangle = -1; // triangle index within its mesh (MeshTriangles order)
    bool hit() const { return instance >= 0; }
};

} // namespace glint::bvh
