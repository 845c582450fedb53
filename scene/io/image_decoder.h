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

// The chunk of an OpenEXR file's first part, for which OpenEXR allocates its buffers on opening
// whatever the image's size: a tiled file's tile, or a scanline file's width by the lines its
// compression packs in one chunk (1 to 256). Its size in pixels, its channels and their widest value
// in bytes. None for other files or where the header does not say.
struct ExrChunkShape {
    std::int64_t width = 0;
    std::int64_t height = 0;
    std::int64_t channels = 0;
    std::size_t bytesPerValue = 0;
};
std::optional<ExrChunkShape> probeExrChunk(std::span<const std::uint8_t> bytes);

struct DecodeLimits {
    std::uint64_t maxPixels = 16384ull * 16384ull;
    std::uint64_t maxBytes = 1ull << 31; // of the decoded pixels: width x height x channels x bytes per value
};

// Why an image whose header declares width x height pixels of `channels` channels may not be
// decoded into `decodedChannels` values of `bytesPerValue` bytes per pixel, naming the limit it
// exceeds; empty when it may. Checked on the header before any pixel buffer is allocated (an image
// bomb: a few bytes declaring 65535 x 65535 pixels or thousands of channels).
std::string decodeLimitError(std::int64_t width, std::int64_t height, std::int64_t channels, int decodedChannels,
                             std::size_t bytesPerValue, const DecodeLimits& limits);

// What in an image file's first bytes declares more than the file of `fileSize` bytes can hold,
// where an image library would allocate the declared size before reading it: a PNG chunk's length
// (libpng), an OpenEXR attribute's size or value, or its table of chunk offsets (OpenEXR). Empty
// when nothing does.
std::string imageHeaderProblem(std::span<const std::uint8_t> header, std::uint64_t fileSize);

// The same for the buffer an image library reads one tile or strip into (OpenImageIO: a tile, or
// a TIFF strip of its RowsPerStrip rows, whatever the image's own height): `chunkWidth` x
// `chunkHeight` pixels of `channels` values of `bytesPerValue` bytes.
std::string chunkLimitError(std::int64_t chunkWidth, std::int64_t chunkHeight, std::int64_t channels, std::size_t bytesPerValue,
                            const DecodeLimits& limits);

// Why an image file may not be opened, from its first bytes (`header`) and its size: the size
// probeImageHeader reads beyond the limits (one channel assumed), an OpenEXR chunk beyond them
// (probeExrChunk), or an imageHeaderProblem. So an
// image bomb is refused before an image library opens it: some allocate for the declared size on
// opening (libjpeg for a progressive JPEG's coefficients, libpng for a chunk, OpenEXR for its
// attributes). Empty when neither applies.
std::string headerLimitError(std::span<const std::uint8_t> header, std::uint64_t fileSize, int decodedChannels,
                             std::size_t bytesPerValue, const DecodeLimits& limits);

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
