#pragma once
// An equirectangular map as the path tracer reads it: GL_LINEAR between pixel centres, GL_REPEAT in
// u (longitude), GL_CLAMP_TO_EDGE in v. For the tests that check sampling and lighting against the
// map as it is read, not as it is stored.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace glint::test {

// The read at (u, v) of `rgb` (width * height * 3 floats, row 0 at the top), as weights . RGB.
inline double bilinearMapRead(const std::vector<float>& rgb, int width, int height, double u, double v,
                              const std::array<double, 3>& weights) {
    const auto at = [&](int x, int y) {
        x = (x % width + width) % width;
        y = std::clamp(y, 0, height - 1);
        const float* p = &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
        return weights[0] * p[0] + weights[1] * p[1] + weights[2] * p[2];
    };
    const double x = u * width - 0.5, y = v * height - 0.5;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

} // namespace glint::test
