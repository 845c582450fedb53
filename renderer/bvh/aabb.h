#pragma once
// Axis-aligned boxes. An empty box has lo = +inf and hi = -inf, so growing it by anything works.
#include <glm/glm.hpp>

#include <limits>

namespace glint::bvh {

struct Aabb {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};

    void grow(const glm::vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    void grow(const Aabb& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    glm::vec3 extent() const { return hi - lo; }
    glm::vec3 centre() const { return 0.5f * (lo + hi); }
    // 0 for an empty box (so empty leaves cost nothing in the SAH).
    float surfaceArea() const
    {
        if (empty()) return 0.0f;
        const glm::vec3 e = extent();
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
    bool contains(const Aabb& b) const
    {
        return b.empty() || (glm::all(glm::lessThanEqual(lo, b.lo)) && glm::all(glm::greaterThanEqual(hi, b.hi)));
    }
    friend bool operator==(const Aabb&, const Aabb&) = default;
};

// The box around `local` after `worldFromLocal` (its eight corners, so exact for affine maps).
Aabb transformed(const Aabb& local, const glm::mat4& worldFromLocal);

} // namespace glint::bvh
