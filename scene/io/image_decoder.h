#pragma once
// Image decoding behind a small interface, so that sanitizer and fuzz builds of the scene library
// need not load OpenImageIO (the implementation lives in oiio/, library glint_image_oiio).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glint {

struct ImageSize {
    int width = 0;
    int height = 0;
    friend bool operator==(const ImageSize&, const ImageSize&) = default;
};

// Dimensions from the header bytes of a PNG, JPEG, Radiance HDR or OpenEXR file, without any
// image library and without decoding pixels: enough to refuse a header claiming 65535x65535.
std::optional<ImageSize> probeImageHeader(std::span<const std::uint8_t> bytes);

struct DecodeLimits {
    std::uint64_t maxPixels = 16384ull * 16384ull;
    std::uint64_t maxBytes = 1ull << 31; // of the decoded RGBA pixels
};

// Decoded pixels, RGBA, rows top to bottom. Empty pixels and a message when decoding failed.
template <class T>
struct DecodedImage {
    int width = 0;
    int height = 0;
    std::vector<T> rgba;
    std::string error;
    bool ok() const { return error.empty() && !rgba.empty(); }
};

class ImageDecoder {
public:
    virtual ~ImageDecoder() = default;
    // Dimensions from the header only (nothing when the format is unknown or the header is broken).
    virtual std::optional<ImageSize> probe(std::span<const std::uint8_t> encoded) const = 0;
    // Linear floats as the file stores them (no colour conversion), for HDR environments and textures.
    virtual DecodedImage<float> decodeFloat(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const = 0;
    // 8-bit values as stored (sRGB textures stay sRGB-encoded).
    virtual DecodedImage<std::uint8_t> decode8(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const = 0;
};

} // namespace glint
