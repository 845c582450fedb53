#include "renderer/render_region.h"

#include <algorithm>
#include <cmath>

namespace glint::renderer {

PixelRect regionPixels(const RenderRegion& region, int width, int height) {
    if (!region.active || width <= 0 || height <= 0) return {0, 0, std::max(width, 0), std::max(height, 0)};
    const auto clampTo = [](double v, int limit) { return std::clamp(static_cast<int>(v), 0, limit); };
    // Top-down fractions to covered pixel columns and rows (floor of the start, ceiling of the end).
    const int left = clampTo(std::floor(double(region.x) * width), width - 1);
    const int right = std::max(left + 1, clampTo(std::ceil(double(region.x + region.width) * width), width));
    const int top = clampTo(std::floor(double(region.y) * height), height - 1);
    const int bottom = std::max(top + 1, clampTo(std::ceil(double(region.y + region.height) * height), height));
    return {left, height - bottom, right - left, bottom - top};
}

} // namespace glint::renderer
