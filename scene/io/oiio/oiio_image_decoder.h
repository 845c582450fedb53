#pragma once
// ImageDecoder through OpenImageIO (PNG, JPEG, TIFF, HDR, EXR), reading from memory.
#include "scene/io/image_decoder.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace glint {

// The limits checked on an opened image's spec, before any pixel buffer exists: its size, its
// channels and its values as stored or as read (the larger), its tiles or TIFF strips (OpenImageIO
// reads one at a time into a buffer of the declared size), and no deep data.
std::string openedLimitError(const OIIO::ImageSpec& spec, int decodedChannels, std::size_t bytesPerValue, const DecodeLimits& limits);

// The name OpenImageIO picks the reader by for these bytes ("memory.png", ".jpg", ".hdr", ".exr",
// ".tif" after their signature), or null when the signature is none of those.
const char* memoryImageName(std::span<const std::uint8_t> encoded);

// An in-memory file for OpenImageIO's readers. OpenImageIO 2.4's IOMemReader copies from before its
// buffer when asked to read at an offset between -size and 0 (its bounds check wraps around; fixed
// upstream in 2026): a corrupt OpenEXR offset table made it do so. Any offset outside the buffer
// reads nothing here, as a file read past its end would.
class BoundedMemReader final : public OIIO::Filesystem::IOMemReader {
public:
    using IOMemReader::IOMemReader;
    std::size_t pread(void* buf, std::size_t size, std::int64_t offset) override;
};

// Bytes opened by the one reader their signature names. OpenImageIO's own open() hands bytes that
// reader refuses to every other reader it has (a dozen parsers, a camera-raw library among them):
// more code exposed to a broken file, and about 0.5 ms per refusal where this takes microseconds.
// A JPEG is opened without its metadata (jpegWithoutMetadata).
struct MemoryImage {
    std::vector<std::uint8_t> jpeg;          // a JPEG's bytes less its metadata; empty for other files
    std::unique_ptr<BoundedMemReader> bytes; // the reader reads through it: declared before the reader, freed after
    std::unique_ptr<OIIO::ImageInput> input; // null when the bytes did not open
    std::string error;                       // why not: no known signature, or the reader's complaint
};
MemoryImage openImageFromMemory(std::span<const std::uint8_t> encoded);

// Channels 0 .. channels - 1 of the opened image, converted to `type` into `out`, a pixel every
// `pixelStride` bytes and rows packed. The values are read as stored and converted here:
// OpenImageIO 2.4 converts through a 64 MiB scratch buffer whatever the image's size. False: the
// input's geterror() says why.
bool readConvertedPixels(OIIO::ImageInput& input, int channels, OIIO::TypeDesc type, void* out, std::size_t pixelStride);

class OiioImageDecoder final : public ImageDecoder {
public:
    std::optional<ImageSize> probe(std::span<const std::uint8_t> encoded) const override;
    DecodedImage<float> decodeFloat(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const override;
    DecodedImage<std::uint8_t> decode8(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const override;
};

} // namespace glint
