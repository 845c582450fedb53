#pragma once
// Statistics over rendered images (RGBA float, rows top-down).
#include <cmath>
#include <vector>

namespace glint::test {

struct ChannelStats {
    double mean = 0.0;
    double stddev = 0.0;
    double minimum = 0.0;
    double maximum = 0.0;
};

// Over every pixel's channel `c` of an RGBA image.
inline ChannelStats channelStats(const std::vector<float>& rgba, int c) {
    ChannelStats s;
    double sum = 0.0, sum2 = 0.0;
    s.minimum = 1e300;
    s.maximum = -1e300;
    const std::size_t n = rgba.size() / 4;
    for (std::size_t i = 0; i < n; ++i) {
        const double v = rgba[i * 4 + static_cast<std::size_t>(c)];
        sum += v;
        sum2 += v * v;
        s.minimum = std::min(s.minimum, v);
        s.maximum = std::max(s.maximum, v);
    }
    s.mean = sum / static_cast<double>(n);
    s.stddev = std::sqrt(std::max(sum2 / static_cast<double>(n) - s.mean * s.mean, 0.0));
    return s;
}

inline float pixel(const std::vector<float>& rgba, int width, int x, int y, int c) {
    return rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4 + static_cast<std::size_t>(c)];
}

} // namespace glint::test
