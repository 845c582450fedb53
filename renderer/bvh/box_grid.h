#pragma once
// Node boxes on a 16-bit grid per BVH level (bvh_layout.h): a walk step reads each child's box and
// link from one texel instead of two. Rounding is outward, so a quantised box always holds the box
// it stands for and a ray can only visit more nodes, never miss a triangle.
#include "renderer/bvh/aabb.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>

namespace glint::bvh {

inline constexpr std::uint32_t kGridMax = 65535;
// Every box within +-kGridReach fits a grid (kGridMax steps of the largest scale span more than
// twice that); the BVH builders treat boxes beyond it as they treat non-finite ones: unhittable.
inline constexpr float kGridReach = 8.0e37f;

bool withinGridReach(const Aabb& box);

// A level's grid: corner = origin + float(q) * scale for q in [0, kGridMax], scale a power of two
// per axis (so q * scale is exact and the sum is the one rounding, on the CPU and the GPU alike).
struct BoxGrid {
    glm::vec3 origin{0.0f};
    glm::vec3 scale{1.0f};
    friend bool operator==(const BoxGrid&, const BoxGrid&) = default;
};

struct GridBox {
    glm::uvec3 lo{0};
    glm::uvec3 hi{0};
};

// The finest grid whose span holds `root`, with `root.lo` at q = 0; an empty root, or one beyond
// kGridReach (non-finite ones included), gets the unit grid at 0.
BoxGrid gridAround(const Aabb& root);

// `box` rounded outwards to the grid, or nullopt where it reaches beyond the grid's span or beyond
// kGridReach. An empty box becomes the grid's origin point.
std::optional<GridBox> quantize(const BoxGrid& grid, const Aabb& box);

glm::vec3 gridPoint(const BoxGrid& grid, glm::uvec3 q);
Aabb dequantize(const BoxGrid& grid, const GridBox& box);

// A node texel's first three words: lo | hi << 16 per axis.
glm::uvec3 packGridBox(const GridBox& box);
GridBox unpackGridBox(glm::uvec3 packed);

} // namespace glint::bvh
