#include "oiio_image_decoder.h"

#include "scene/io/jpeg_segments.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

namespace glint {

namespace {

namespace OIIO = OIIO_NAMESPACE;

} // namespace

// OpenImageIO picks its reader by file name: name the bytes after their signature.
const char* memoryImageName(std::span<const std::uint8_t> b)
{
    auto has = [&](std::initializer_list<std::uint8_t> magic) {
        return b.size() >= magic.size() && std::equal(magic.begin(), magic.end(), b.begin());
    };
    if (has({0x89, 'P', 'N', 'G'})) return "memory.png";
    if (has({0xFF, 0xD8})) return "memory.jpg";
    if (has({'#', '?'})) return "memory.hdr";
    if (has({0x76, 0x2f, 0x31, 0x01})) return "memory.exr";
    if (has({'I', 'I', 42, 0}) || has({'M', 'M', 0, 42})) return "memory.tif";
    return nullptr;
}

std::size_t BoundedMemReader::pread(void* buf, std::size_t size, std::int64_t offset)
{
    const auto length = static_cast<std::int64_t>(buffer().size());
    if (offset < 0 || offset >= length) return 0;
    return IOMemReader::pread(buf, std::min(size, static_cast<std::size_t>(length - offset)), offset);
}

MemoryImage openImageFromMemory(std::span<const std::uint8_t> encoded)
{
    MemoryImage opened;
    const char* name = memoryImageName(encoded);
    if (!name) {
        opened.error = "not a PNG, JPEG, HDR, EXR or TIFF file";
        return opened;
    }
    // Created by the bare extension, OpenImageIO returns that reader unopened and tries no other.
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(OIIO::Filesystem::extension(name, false));
    if (!input) {
        opened.error = OIIO::geterror();
        return opened;
    }
    if (name == std::string_view("memory.jpg")) {
        opened.jpeg = jpegWithoutMetadata(encoded);
        encoded = opened.jpeg;
    }
    opened.bytes = std::make_unique<BoundedMemReader>(encoded.data(), encoded.size());
    OIIO::ImageSpec spec;
    if (!input->set_ioproxy(opened.bytes.get()) || !input->open(name, spec)) {
        opened.error = input->geterror();
        if (opened.error.empty()) opened.error = "not an image OpenImageIO can read";
        return opened;
    }
    opened.input = std::move(input);
    return opened;
}

bool readConvertedPixels(OIIO::ImageInput& input, int channels, OIIO::TypeDesc type, void* out, std::size_t pixelStride)
{
    const OIIO::ImageSpec& spec = input.spec();
    if (!spec.channelformats.empty()) // values stored in several types: OpenImageIO converts each
        return input.read_image(0, 0, 0, channels, type, out, static_cast<OIIO::stride_t>(pixelStride));
    std::vector<std::byte> stored(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                                  static_cast<std::size_t>(channels) * spec.format.size());
    if (!input.read_image(0, 0, 0, channels, OIIO::TypeDesc::UNKNOWN, stored.data())) return false;
    return OIIO::convert_image(channels, spec.width, spec.height, 1, stored.data(), spec.format, OIIO::AutoStride, OIIO::AutoStride,
                               OIIO::AutoStride, out, type, static_cast<OIIO::stride_t>(pixelStride), OIIO::AutoStride, OIIO::AutoStride);
}

namespace {

template <class T>
DecodedImage<T> decode(std::span<const std::uint8_t> encoded, const DecodeLimits& limits, OIIO::TypeDesc type)
{
    DecodedImage<T> out;
    // Glint's own header checks first: libjpeg allocates a progressive JPEG's coefficients for the
    // declared size when OpenImageIO opens it, OpenEXR an attribute's declared size.
    out.error = headerLimitError(encoded, encoded.size(), 4, sizeof(T), limits);
    if (!out.error.empty()) return out;
    MemoryImage opened = openImageFromMemory(encoded);
    if (!opened.input) {
        out.error = opened.error;
        return out;
    }
    const OIIO::ImageSpec& spec = opened.input->spec();
    // The header's size against the limits before anything is allocated for the pixels.
    out.error = openedLimitError(spec, 4, sizeof(T), limits);
    if (!out.error.empty()) return out;
    const auto pixels = static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height);
    out.width = spec.width;
    out.height = spec.height;
    out.rgba.assign(pixels * 4, spec.nchannels >= 4 ? T(0) : type == OIIO::TypeDesc::FLOAT ? T(1) : T(255));
    const int channels = std::min(spec.nchannels, 4);
    if (!readConvertedPixels(*opened.input, channels, type, out.rgba.data(), 4 * sizeof(T))) {
        out.error = opened.input->geterror();
        out.rgba.clear();
        return out;
    }
    if (channels < 3) { // grey (+ alpha): spread the grey over RGB
        for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
            if (channels == 2) out.rgba[i + 3] = out.rgba[i + 1];
            out.rgba[i + 1] = out.rgba[i + 2] = out.rgba[i];
        }
    }
    return out;
}

} // namespace

std::string openedLimitError(const OIIO::ImageSpec& spec, int decodedChannels, std::size_t bytesPerValue, const DecodeLimits& limits)
{
    if (spec.deep) return "deep images are not read";
    const std::size_t perValue = std::max(bytesPerValue, spec.format.size()); // as stored or as read, the larger
    if (std::string error = decodeLimitError(spec.width, spec.height, spec.nchannels, decodedChannels, perValue, limits); !error.empty())
        return error;
    // OpenImageIO reads a tile, or a TIFF strip of RowsPerStrip rows, at a time: a strip declared
    // 10784 rows high in a 5-row image made it allocate 8 GB.
    const bool tiled = spec.tile_width > 0 && spec.tile_height > 0;
    const std::int64_t chunkWidth = tiled ? spec.tile_width : spec.width;
    const std::int64_t chunkHeight = tiled ? std::int64_t(spec.tile_height) * std::max(1, spec.tile_depth)
                                           : std::max(1, spec.get_int_attribute("tiff:RowsPerStrip", 1));
    return chunkLimitError(chunkWidth, chunkHeight, spec.nchannels, perValue, limits);
}

std::optional<ImageSize> OiioImageDecoder::probe(std::span<const std::uint8_t> encoded) const
{
    // Read without OpenImageIO where Glint's probe can: opening may allocate for the declared size.
    if (auto size = probeImageHeader(encoded)) return size;
    if (!imageHeaderProblem(encoded, encoded.size()).empty()) return std::nullopt;
    MemoryImage opened = openImageFromMemory(encoded);
    if (!opened.input) return std::nullopt;
    return ImageSize{opened.input->spec().width, opened.input->spec().height};
}

DecodedImage<float> OiioImageDecoder::decodeFloat(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const
{
    return decode<float>(encoded, limits, OIIO::TypeDesc::FLOAT);
}

DecodedImage<std::uint8_t> OiioImageDecoder::decode8(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const
{
    return decode<std::uint8_t>(encoded, limits, OIIO::TypeDesc::UINT8);
}

} // namespace glint
