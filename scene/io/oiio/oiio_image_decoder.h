#pragma once
// ImageDecoder through OpenImageIO (PNG, JPEG, TIFF, HDR, EXR), reading from memory.
#include "scene/io/image_decoder.h"

namespace glint {

// The name OpenImageIO picks the reader by for these bytes ("memory.png", ".jpg", ".hdr", ".exr",
// ".tif" after their signature), or null when the signature is none of those.
const char* memoryImageName(std::span<const std::uint8_t> encoded);

class OiioImageDecoder final : public ImageDecoder {
public:
    std::optional<ImageSize> probe(std::span<const std::uint8_t> encoded) const override;
    DecodedImage<float> decodeFloat(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const override;
    DecodedImage<std::uint8_t> decode8(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const override;
};

} // namespace glint
