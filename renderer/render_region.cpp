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

ImageWindow imageWindowOf(const PixelRect& rect, int height) {
    return {rect.x, height - rect.y - rect.height, rect.width, rect.height};
}

PixelRect pixelRectOf(const ImageWindow& window, int height) {
    return {window.x, height - window.y - window.height, window.width, window.height};
}

RenderRegion regionOfWindow(const ImageWindow& window, int width, int height) {
    const auto fraction = [](double pixels, int size) { return static_cast<float>(pixels / size); };
    RenderRegion region;
    region.active = true;
    region.x = fraction(window.x + 0.25, width);
    region.y = fraction(window.y + 0.25, height);
    region.width = fraction(window.width - 0.5, width);
    region.height = fraction(window.height - 0.5, height);
    return region;
}

PixelRect grown(const PixelRect& rect, int margin, int width, int height) {
    const int left = std::max(rect.x - margin, 0);
    const int bottom = std::max(rect.y - margin, 0);
    const int right = std::min(rect.x + rect.width + margin, width);
    const int top = std::min(rect.y + rect.height + margin, height);
    return {left, bottom, std::max(right - left, 0), std::max(top - bottom, 0)};
}

} // namespace glint::renderer
