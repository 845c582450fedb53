#include "editor/viewport/debug_image.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace glint::editor {

namespace {

int toByte(float v) { return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// Largest finite value of one channel group, for normalising (1 when there is none).
float largestFinite(const std::vector<float>& values) {
    float m = 0.0f;
    for (const float v : values)
        if (std::isfinite(v)) m = std::max(m, std::abs(v));
    return m > 0.0f ? m : 1.0f;
}

// Cost per pixel of the BvhCost variant: radiance.r (RGBA).
float costAt(const renderer::FrameImages& images, std::size_t pixel) { return images.radiance[4 * pixel]; }

QImage heatImage(const renderer::FrameImages& images) {
    QImage out(images.width, images.height, QImage::Format_RGB32);
    out.fill(Qt::black);
    const std::size_t n = std::size_t(images.width) * std::size_t(images.height);
    if (images.radiance.size() < 4 * n) return out;
    const float top = bvhCostScale(images);
    out.setText(kCostScaleKey, QString::number(double(top)));
    const float scale = 1.0f / top;
    for (int y = 0; y < images.height; ++y) {
        auto* row = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < images.width; ++x)
            row[x] = heatColour(costAt(images, std::size_t(y) * std::size_t(images.width) + std::size_t(x)) * scale).rgb();
    }
    return out;
}

} // namespace

QColor heatColour(float t) {
    // Black, blue, cyan, green, yellow, red: ordered by lightness first, then hue, so that both
    // "none" and "a lot" are easy to tell apart from the middle of the scale.
    static constexpr float stops[][3] = {{0, 0, 0}, {0.1f, 0.2f, 0.9f}, {0, 0.8f, 0.9f}, {0.1f, 0.85f, 0.2f}, {1, 0.9f, 0.1f}, {0.95f, 0.1f, 0.05f}};
    constexpr int last = int(std::size(stops)) - 1;
    if (!(t > 0.0f)) return QColor(0, 0, 0);
    const float x = std::min(t, 1.0f) * float(last);
    const int i = std::min(int(x), last - 1);
    const float f = x - float(i);
    const auto mixed = [&](int c) { return toByte(stops[i][c] + (stops[i + 1][c] - stops[i][c]) * f); };
    return QColor(mixed(0), mixed(1), mixed(2));
}

float bvhCostScale(const renderer::FrameImages& images) {
    float largest = 0.0f;
    const std::size_t n = std::min(images.radiance.size() / 4, std::size_t(images.width) * std::size_t(images.height));
    for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(costAt(images, i))) largest = std::max(largest, costAt(images, i));
    float step = 1.0f;
    while (step * 10.0f < largest) step *= 10.0f;
    for (const float m : {1.0f, 2.0f, 5.0f, 10.0f})
        if (largest <= m * step) return m * step;
    return 10.0f * step;
}

QImage debugImage(const renderer::FrameImages& images, ViewMode mode) {
    if (mode == ViewMode::BvhCost) return heatImage(images);
    QImage out(images.width, images.height, QImage::Format_RGB32);
    out.fill(Qt::black);
    const std::size_t n = std::size_t(images.width) * std::size_t(images.height);
    const std::vector<float>* source = nullptr;
    int channels = 3;
    float scale = 1.0f, bias = 0.0f;
    switch (mode) {
    case ViewMode::Normals: source = &images.normal; scale = 0.5f; bias = 0.5f; break;
    case ViewMode::Albedo: source = &images.albedo; break;
    case ViewMode::Motion: source = &images.motion; channels = 2; scale = 0.5f / std::max(1.0f, largestFinite(images.motion)); bias = 0.5f; break;
    case ViewMode::Variance: source = &images.variance; scale = 1.0f / largestFinite(images.variance); break;
    case ViewMode::Depth: source = &images.depth; channels = 1; scale = 1.0f / largestFinite(images.depth); break;
    default: return out;
    }
    if (source->size() < n * std::size_t(channels)) return out;
    for (int y = 0; y < images.height; ++y) {
        auto* row = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < images.width; ++x) {
            const float* p = source->data() + (std::size_t(y) * std::size_t(images.width) + std::size_t(x)) * std::size_t(channels);
            const auto channel = [&](int c) { return toByte(p[std::min(c, channels - 1)] * scale + bias); };
            row[x] = channels == 2 ? qRgb(channel(0), channel(1), toByte(bias)) : qRgb(channel(0), channel(1), channel(2));
        }
    }
    return out;
}

} // namespace glint::editor
