#pragma once
// Watertight ray/triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013): rays through a shared edge or vertex of a closed mesh hit at least one
// of its triangles. Twin of shaders/bvh/triangle.glsl; both avoid fused multiply-adds.
#include "renderer/bvh/ray.h"

#include <glm/glm.hpp>

namespace glint::bvh {

// Per-ray constants: the permutation that makes z the dominant direction axis and the shear.
struct WatertightRay {
    glm::vec3 origin{0.0f};
    int kx = 0, ky = 1, kz = 2;
    float sx = 0.0f, sy = 0.0f, sz = 1.0f;
};

WatertightRay prepareWatertight(const Ray& ray);

struct TriangleHit {
    float t = 0.0f, u = 0.0f, v = 0.0f;
};

// True for a hit with tMin < t < tMax (both faces).
bool intersectTriangle(const WatertightRay& ray, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                       float tMin, float tMax, TriangleHit& hit);

} // namespace glint::bvh
