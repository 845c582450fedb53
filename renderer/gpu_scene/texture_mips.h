#pragma once
// CPU mipmaps for material textures: a deterministic 2x2 box filter (driver glGenerateMipmap
// filters differ between vendors), averaged in linear light for sRGB images. CPU only: no GL here
// (library glint_renderer_image, which the scene-only build fuzzes).
#include "scene/io/image_decoder.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace glint::renderer {

// One RGBA8 image level, rows in upload order.
struct TextureLevel {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// Levels 0 .. 1x1 of one image.
using MipChain = std::vector<TextureLevel>;

// The sRGB transfer function of IEC 61966-2-1 (exact piecewise form, not a gamma of 2.2).
float srgbToLinear(std::uint8_t encoded);
std::uint8_t linearToSrgb8(float linear); // rounded to the nearest code

// Levels 0 .. 1x1. Each texel of level n+1 averages the 2x2 texels (2x, 2y) .. (2x+1, 2y+1) of level
// n, the odd last row or column of an odd-sized level folded into its neighbour by clamping. Colour
// channels of an sRGB image are averaged as linear values and re-encoded; alpha is always linear.
std::vector<TextureLevel> buildMipChain(TextureLevel base, bool srgb);

// One level halved: level 1 of buildMipChain(level, srgb), without the levels after it.
TextureLevel halveLevel(const TextureLevel& level, bool srgb);

// An encoded image decoded (8-bit) within `limits`, halved until neither side exceeds `maxSize`,
// and its mip chain built; or why it could not be decoded (no levels).
struct DecodedMipChain {
    MipChain levels;
    std::string error;
};
DecodedMipChain decodeMipChain(const ImageDecoder& decoder, std::span<const std::uint8_t> encoded, bool srgb, int maxSize,
                               const DecodeLimits& limits = {});

// Bilinear resampling to another size (texel centres aligned, edges clamped), in linear light for
// sRGB images: used only when the scene has more texture sizes than sampler units.
TextureLevel resampleLevel(const TextureLevel& level, int width, int height, bool srgb);

} // namespace glint::renderer
