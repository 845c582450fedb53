#include "renderer/bvh/box_grid.h"

#include <algorithm>
#include <cmath>

namespace glint::bvh {
namespace {

constexpr int kMinScaleExponent = -126; // the smallest normal float: q * scale stays exact
constexpr int kMaxScaleExponent = 111;  // kGridMax * 2^111 is still finite

float axisPoint(float origin, float scale, std::uint32_t q)
{
    return origin + static_cast<float>(q) * scale;
}

// The smallest power of two whose kGridMax steps from lo reach hi, as the float sum computes it,
// and no finer than the floats there: one step then always moves a grid point, so quantize()'s
// estimate is off by a step at most. (A flat axis at 2.5 had steps of 2^-126 that moved nothing,
// and each box took 65,535 passes to round.)
float axisScale(float lo, float hi)
{
    int exponent = kMinScaleExponent;
    const float largest = std::max(std::abs(lo), std::abs(hi));
    if (largest > 0.0f) exponent = std::max(exponent, std::ilogb(largest) - 23); // its ulp
    const double step = (static_cast<double>(hi) - lo) / kGridMax;
    if (step > 0.0) exponent = std::max(exponent, std::ilogb(step));
    while (exponent < kMaxScaleExponent && axisPoint(lo, std::ldexp(1.0f, exponent), kGridMax) < hi) ++exponent;
    return std::ldexp(1.0f, exponent);
}

std::uint32_t clampToGrid(double q)
{
    return static_cast<std::uint32_t>(std::clamp(q, 0.0, static_cast<double>(kGridMax)));
}

// The largest q whose point is at or below lo, and the smallest at or above hi.
std::optional<glm::uvec2> quantizeAxis(float origin, float scale, float lo, float hi)
{
    std::uint32_t qlo = clampToGrid(std::floor((static_cast<double>(lo) - origin) / scale));
    while (qlo > 0 && axisPoint(origin, scale, qlo) > lo) --qlo;
    while (qlo < kGridMax && axisPoint(origin, scale, qlo + 1) <= lo) ++qlo;
    std::uint32_t qhi = clampToGrid(std::ceil((static_cast<double>(hi) - origin) / scale));
    while (qhi < kGridMax && axisPoint(origin, scale, qhi) < hi) ++qhi;
    while (qhi > 0 && axisPoint(origin, scale, qhi - 1) >= hi) --qhi;
    if (axisPoint(origin, scale, qlo) > lo || axisPoint(origin, scale, qhi) < hi) return std::nullopt;
    return glm::uvec2(qlo, qhi);
}

} // namespace

bool withinGridReach(const Aabb& box)
{
    const auto inReach = [](const glm::vec3& p) { return glm::all(glm::lessThanEqual(glm::abs(p), glm::vec3(kGridReach))); };
    return inReach(box.lo) && inReach(box.hi); // false for NaN as well
}

BoxGrid gridAround(const Aabb& root)
{
    BoxGrid grid;
    if (root.empty() || !withinGridReach(root)) return grid;
    grid.origin = root.lo;
    for (int axis = 0; axis < 3; ++axis) grid.scale[axis] = axisScale(root.lo[axis], root.hi[axis]);
    return grid;
}

std::optional<GridBox> quantize(const BoxGrid& grid, const Aabb& box)
{
    if (box.empty()) return GridBox{};
    if (!withinGridReach(box)) return std::nullopt;
    GridBox out;
    for (int axis = 0; axis < 3; ++axis) {
        const auto q = quantizeAxis(grid.origin[axis], grid.scale[axis], box.lo[axis], box.hi[axis]);
        if (!q) return std::nullopt;
        out.lo[axis] = q->x;
        out.hi[axis] = q->y;
    }
    return out;
}

glm::vec3 gridPoint(const BoxGrid& grid, glm::uvec3 q)
{
    return {axisPoint(grid.origin.x, grid.scale.x, q.x), axisPoint(grid.origin.y, grid.scale.y, q.y),
            axisPoint(grid.origin.z, grid.scale.z, q.z)};
}

Aabb dequantize(const BoxGrid& grid, const GridBox& box)
{
    return Aabb{gridPoint(grid, box.lo), gridPoint(grid, box.hi)};
}

glm::uvec3 packGridBox(const GridBox& box)
{
    return box.lo | (box.hi << 16u);
}

GridBox unpackGridBox(glm::uvec3 packed)
{
    return GridBox{packed & glm::uvec3(0xFFFFu), packed >> 16u};
}

} // namespace glint::bvh
