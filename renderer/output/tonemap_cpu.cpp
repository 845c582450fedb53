#include "renderer/output/tonemap_cpu.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace glint::video {

namespace {

using Rgb = std::array<float, 3>;

// Beyond this every curve is white; above it ACES's squares overflow to inf / inf = NaN (black).
// The same ceiling as shaders/passes/tonemap_curves.glsl.
constexpr float kTonemapCeiling = 1.0e6f;

// GLSL's mat3 is column-major: columns are listed in the shader's constructor order.
Rgb multiply(const std::array<float, 9>& columns, const Rgb& v) {
    Rgb out{};
    for (int r = 0; r < 3; ++r)
        out[std::size_t(r)] = columns[std::size_t(r)] * v[0] + columns[std::size_t(3 + r)] * v[1] + columns[std::size_t(6 + r)] * v[2];
    return out;
}

Rgb acesFitted(const Rgb& color) {
    constexpr std::array<float, 9> in{0.59719f, 0.07600f, 0.02840f, 0.35458f, 0.90834f, 0.13383f, 0.04823f, 0.01566f, 0.83777f};
    constexpr std::array<float, 9> out{1.60475f, -0.10208f, -0.00327f, -0.53108f, 1.10813f, -0.07276f, -0.07367f, -0.00605f, 1.07602f};
    Rgb v = multiply(in, color);
    for (float& x : v) {
        const float a = x * (x + 0.0245786f) - 0.000090537f;
        const float b = x * (0.983729f * x + 0.4329510f) + 0.238081f;
        x = a / b;
    }
    return multiply(out, v);
}

Rgb pbrNeutral(Rgb color) {
    constexpr float startCompression = 0.8f - 0.04f;
    constexpr float desaturation = 0.15f;
    const float x = std::min(color[0], std::min(color[1], color[2]));
    const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    for (float& c : color) c -= offset;
    const float peak = std::max(color[0], std::max(color[1], color[2]));
    if (peak < startCompression) return color;
    constexpr float d = 1.0f - startCompression;
    const float newPeak = 1.0f - d * d / (peak + d - startCompression);
    const float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
    for (float& c : color) c = (c * (newPeak / peak)) * (1.0f - g) + newPeak * g;
    return color;
}

float encodeSrgb(float linear) {
    return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

std::uint8_t toByte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

} // namespace

std::vector<std::uint8_t> tonemapToSrgb8(const std::vector<float>& rgba, float exposureEv, Tonemapper tonemapper) {
    const float scale = std::exp2(exposureEv);
    std::vector<std::uint8_t> out(rgba.size());
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
        Rgb c{std::min(rgba[i] * scale, kTonemapCeiling), std::min(rgba[i + 1] * scale, kTonemapCeiling),
              std::min(rgba[i + 2] * scale, kTonemapCeiling)};
        if (tonemapper == Tonemapper::AcesFitted) c = acesFitted(c);
        else if (tonemapper == Tonemapper::PbrNeutral) c = pbrNeutral(c);
        for (std::size_t k = 0; k < 3; ++k) out[i + k] = toByte(encodeSrgb(std::clamp(c[k], 0.0f, 1.0f)));
        out[i + 3] = toByte(rgba[i + 3]);
    }
    return out;
}

} // namespace glint::video
