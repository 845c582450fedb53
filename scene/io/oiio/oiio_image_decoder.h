#pragma once
// ImageDecoder through OpenImageIO (PNG, JPEG, TIFF, HDR, EXR), reading from memory.
#include "scene/io/image_decoder.h"

#include <OpenImageIO/imageio.h>

namespace glint {

// The limits checked on an opened image's spec, before any pixel buffer exists: its size, its
// channels and its values as stored or as read (the larger), its tiles or TIFF strips (OpenImageIO
// reads one at a time into a buffer of the declared size), and no deep data.
std::string openedLimitError(const OIIO::ImageSpec& spec, int decodedChannels, std::size_t bytesPerValue, const DecodeLimits& limits);

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
