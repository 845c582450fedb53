#include "editor/viewport/debug_image.h"

#include <algorithm>
#include <cmath>

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

} // namespace

QImage debugImage(const renderer::FrameImages& images, ViewMode mode) {
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
