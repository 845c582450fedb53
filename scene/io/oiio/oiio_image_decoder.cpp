#include "oiio_image_decoder.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <memory>

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

namespace {

struct OpenedImage {
    std::unique_ptr<OIIO::Filesystem::IOMemReader> reader;
    std::unique_ptr<OIIO::ImageInput> input;
};

OpenedImage openFromMemory(std::span<const std::uint8_t> encoded)
{
    OpenedImage opened;
    const char* name = memoryImageName(encoded);
    if (!name) return opened;
    opened.reader = std::make_unique<OIIO::Filesystem::IOMemReader>(encoded.data(), encoded.size());
    opened.input = OIIO::ImageInput::open(name, nullptr, opened.reader.get());
    return opened;
}

template <class T>
DecodedImage<T> decode(std::span<const std::uint8_t> encoded, const DecodeLimits& limits, OIIO::TypeDesc type)
{
    DecodedImage<T> out;
    // Glint's own header checks first: libjpeg allocates a progressive JPEG's coefficients for the
    // declared size when OpenImageIO opens it, OpenEXR an attribute's declared size.
    out.error = headerLimitError(encoded, encoded.size(), 4, sizeof(T), limits);
    if (!out.error.empty()) return out;
    OpenedImage opened = openFromMemory(encoded);
    if (!opened.input) {
        out.error = "not an image OpenImageIO can read";
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
    if (!opened.input->read_image(0, 0, 0, channels, type, out.rgba.data(), 4 * sizeof(T))) {
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
    OpenedImage opened = openFromMemory(encoded);
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
