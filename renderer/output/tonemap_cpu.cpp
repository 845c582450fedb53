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

Rgb agx(const Rgb& color) {
    constexpr std::array<float, 9> inset{0.842479062253094f, 0.0423282422610123f, 0.0423756549057051f,
                                         0.0784335999999992f, 0.878468636469772f, 0.0784336f,
                                         0.0792237451477643f, 0.0791661274605434f, 0.879142973793104f};
    constexpr std::array<float, 9> outset{1.19687900512017f, -0.0528968517574562f, -0.0529716355144438f,
                                          -0.0980208811401368f, 1.15190312990417f, -0.0980434501171241f,
                                          -0.0990297440797205f, -0.0989611768448433f, 1.15107367264116f};
    constexpr float minEv = -12.47393f, maxEv = 4.026069f;
    Rgb v = multiply(inset, color);
    for (float& x : v) {
        x = (std::clamp(std::log2(std::max(x, 1.0e-10f)), minEv, maxEv) - minEv) / (maxEv - minEv);
        const float x2 = x * x, x4 = x2 * x2;
        x = 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 + 0.1191f * x - 0.00232f;
    }
    v = multiply(outset, v);
    for (float& x : v) x = std::pow(std::max(x, 0.0f), 2.2f);
    return v;
}

Rgb reinhardExtended(Rgb color) {
    constexpr float white = 4.0f;
    const float l = 0.2126f * color[0] + 0.7152f * color[1] + 0.0722f * color[2];
    if (l <= 0.0f) return Rgb{};
    const float scale = (1.0f + l / (white * white)) / (1.0f + l);
    for (float& c : color) c *= scale;
    return color;
}

float hableCurve(float x) {
    constexpr float A = 0.15f, B = 0.50f, C = 0.10f, D = 0.20f, E = 0.02f, F = 0.30f;
    return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}

Rgb hable(Rgb color) {
    for (float& c : color) c = hableCurve(2.0f * c) / hableCurve(11.2f);
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
        else if (tonemapper == Tonemapper::AgX) c = agx(c);
        else if (tonemapper == Tonemapper::Reinhard) c = reinhardExtended(c);
        else if (tonemapper == Tonemapper::Hable) c = hable(c);
        for (std::size_t k = 0; k < 3; ++k) out[i + k] = toByte(encodeSrgb(std::clamp(c[k], 0.0f, 1.0f)));
        out[i + 3] = toByte(rgba[i + 3]);
    }
    return out;
}

} // namespace glint::video
