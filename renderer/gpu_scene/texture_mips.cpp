#include "renderer/gpu_scene/texture_mips.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace glint::renderer {
namespace {

const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            t[static_cast<std::size_t>(i)] = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return table;
}

std::uint8_t toByte(double unit) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(unit * 255.0), 0L, 255L));
}

// Channel c of texel (x, y) as a linear value in [0, 1].
float linearAt(const TextureLevel& level, int x, int y, int c, bool srgb) {
    const std::uint8_t v = level.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(level.width) + static_cast<std::size_t>(x)) * 4 + static_cast<std::size_t>(c)];
    return srgb && c < 3 ? srgbToLinear(v) : static_cast<float>(v) / 255.0f;
}

std::uint8_t encode(double linear, int c, bool srgb) {
    return srgb && c < 3 ? linearToSrgb8(static_cast<float>(linear)) : toByte(linear);
}

TextureLevel halve(const TextureLevel& src, bool srgb) {
    TextureLevel dst;
    dst.width = std::max(1, src.width / 2);
    dst.height = std::max(1, src.height / 2);
    dst.rgba.resize(static_cast<std::size_t>(dst.width) * static_cast<std::size_t>(dst.height) * 4);
    std::size_t out = 0;
    for (int y = 0; y < dst.height; ++y)
        for (int x = 0; x < dst.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const int x0 = std::min(2 * x, src.width - 1), x1 = std::min(2 * x + 1, src.width - 1);
                const int y0 = std::min(2 * y, src.height - 1), y1 = std::min(2 * y + 1, src.height - 1);
                const double sum = static_cast<double>(linearAt(src, x0, y0, c, srgb)) + linearAt(src, x1, y0, c, srgb) +
                                   linearAt(src, x0, y1, c, srgb) + linearAt(src, x1, y1, c, srgb);
                dst.rgba[out++] = encode(0.25 * sum, c, srgb);
            }
    return dst;
}

} // namespace

float srgbToLinear(std::uint8_t encoded) { return srgbTable()[encoded]; }

std::uint8_t linearToSrgb8(float linear) {
    const double l = std::clamp(static_cast<double>(linear), 0.0, 1.0);
    return toByte(l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055);
}

std::vector<TextureLevel> buildMipChain(TextureLevel base, bool srgb) {
    std::vector<TextureLevel> levels;
    levels.push_back(std::move(base));
    while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(halve(levels.back(), srgb));
    return levels;
}

TextureLevel halveLevel(const TextureLevel& level, bool srgb) { return halve(level, srgb); }

DecodedMipChain decodeMipChain(const ImageDecoder& decoder, std::span<const std::uint8_t> encoded, bool srgb, int maxSize,
                               const DecodeLimits& limits) {
    DecodedImage<std::uint8_t> decoded = decoder.decode8(encoded, limits);
    if (!decoded.ok()) return {{}, decoded.error.empty() ? std::string("the image has no pixels") : decoded.error};
    TextureLevel level{decoded.width, decoded.height, std::move(decoded.rgba)};
    // Halved in the stored values (not linear light) as before, so the bytes stay the same.
    maxSize = std::max(maxSize, 1);
    while (level.width > maxSize || level.height > maxSize) level = halve(level, false);
    return {buildMipChain(std::move(level), srgb), {}};
}

TextureLevel resampleLevel(const TextureLevel& level, int width, int height, bool srgb) {
    TextureLevel out{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)};
    std::size_t i = 0;
    for (int y = 0; y < height; ++y) {
        const double sy = std::clamp((y + 0.5) * level.height / height - 0.5, 0.0, level.height - 1.0);
        const int y0 = static_cast<int>(sy), y1 = std::min(y0 + 1, level.height - 1);
        for (int x = 0; x < width; ++x) {
            const double sx = std::clamp((x + 0.5) * level.width / width - 0.5, 0.0, level.width - 1.0);
            const int x0 = static_cast<int>(sx), x1 = std::min(x0 + 1, level.width - 1);
            const double fx = sx - x0, fy = sy - y0;
            for (int c = 0; c < 4; ++c) {
                const double top = (1 - fx) * linearAt(level, x0, y0, c, srgb) + fx * linearAt(level, x1, y0, c, srgb);
                const double bottom = (1 - fx) * linearAt(level, x0, y1, c, srgb) + fx * linearAt(level, x1, y1, c, srgb);
                out.rgba[i++] = encode((1 - fy) * top + fy * bottom, c, srgb);
            }
        }
    }
    return out;
}

} // namespace glint::renderer
