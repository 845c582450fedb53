// Image dimensions from header bytes. Each format's probe reads only what its header promises and
// checks every offset against the buffer, so truncated or hostile headers give "unknown", never a read
// past the end.
#include "image_decoder.h"
#include "jpeg_segments.h"

#include <algorithm>
#include <cstdio>
#include <string_view>

namespace glint {

namespace {

using Bytes = std::span<const std::uint8_t>;

bool startsWith(Bytes bytes, std::string_view magic)
{
    return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin(),
                                                       [](char m, std::uint8_t b) { return static_cast<std::uint8_t>(m) == b; });
}

std::uint32_t bigEndian32(Bytes b, std::size_t at) { return std::uint32_t(b[at]) << 24 | std::uint32_t(b[at + 1]) << 16 | std::uint32_t(b[at + 2]) << 8 | b[at + 3]; }
std::uint32_t bigEndian16(Bytes b, std::size_t at) { return std::uint32_t(b[at]) << 8 | b[at + 1]; }
std::int32_t littleEndian32(Bytes b, std::size_t at)
{
    return static_cast<std::int32_t>(std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 | std::uint32_t(b[at + 3]) << 24);
}

std::optional<ImageSize> sizeIfPositive(std::int64_t width, std::int64_t height)
{
    if (width <= 0 || height <= 0 || width > INT32_MAX || height > INT32_MAX) return std::nullopt;
    return ImageSize{static_cast<int>(width), static_cast<int>(height)};
}

// Signature, then the IHDR chunk: length, "IHDR", width, height (big-endian).
std::optional<ImageSize> probePng(Bytes b)
{
    if (b.size() < 24 || !startsWith(b.subspan(12), "IHDR")) return std::nullopt;
    return sizeIfPositive(bigEndian32(b, 16), bigEndian32(b, 20));
}

bool isStartOfFrame(std::uint8_t marker)
{
    return marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
}

// The first start-of-frame segment: precision, height, width. Its segment is found as libjpeg finds
// it (jpegSegments), so that a frame header behind garbage is read here too: libjpeg allocates for
// its size on opening.
std::optional<ImageSize> probeJpeg(Bytes b)
{
    for (const JpegSegment& segment : jpegSegments(b, JpegWalk::ToTheFirstScan).segments)
        if (isStartOfFrame(segment.marker))
            return segment.begin + 9 > b.size() ? std::nullopt : sizeIfPositive(bigEndian16(b, segment.begin + 7), bigEndian16(b, segment.begin + 5));
    return std::nullopt; // none before the first scan
}

// Text header lines up to an empty line, then "-Y height +X width".
std::optional<ImageSize> probeHdr(Bytes b)
{
    const std::string_view text(reinterpret_cast<const char*>(b.data()), std::min<std::size_t>(b.size(), 4096));
    const std::size_t blank = text.find("\n\n");
    if (blank == std::string_view::npos) return std::nullopt;
    const std::string_view line = text.substr(blank + 2, text.find('\n', blank + 2) - (blank + 2));
    long long height = 0, width = 0;
    char ySign = 0, xSign = 0;
    const std::string copy(line);
    if (std::sscanf(copy.c_str(), "%cY %lld %cX %lld", &ySign, &height, &xSign, &width) != 4) return std::nullopt;
    return sizeIfPositive(width, height);
}

// Calls visit(name, type, value) for each attribute (name\0 type\0 size data) of an OpenEXR file's
// first header, up to the empty name that ends it, while it lies whole in `b` and until visit
// returns true.
template <class Visit>
void forEachExrAttribute(Bytes b, Visit visit)
{
    std::size_t at = 8;
    while (at < b.size() && b[at] != 0) {
        const auto nameEnd = std::find(b.begin() + static_cast<std::ptrdiff_t>(at), b.end(), 0);
        const auto typeEnd = nameEnd == b.end() ? b.end() : std::find(nameEnd + 1, b.end(), 0);
        if (typeEnd == b.end()) return;
        const std::string_view name(reinterpret_cast<const char*>(&b[at]), static_cast<std::size_t>(nameEnd - b.begin()) - at);
        const std::string_view type(reinterpret_cast<const char*>(&*(nameEnd + 1)), static_cast<std::size_t>(typeEnd - nameEnd - 1));
        const std::size_t sizeAt = static_cast<std::size_t>(typeEnd - b.begin()) + 1;
        if (sizeAt + 4 > b.size()) return;
        const std::int64_t size = littleEndian32(b, sizeAt);
        const std::size_t dataAt = sizeAt + 4;
        if (size < 0 || dataAt + static_cast<std::size_t>(size) > b.size()) return;
        if (visit(name, type, b.subspan(dataAt, static_cast<std::size_t>(size)))) return;
        at = dataAt + static_cast<std::size_t>(size);
    }
}

// dataWindow is a box2i (xMin yMin xMax yMax). OpenEXR reads every attribute of a header in turn,
// a later one of a name replacing an earlier: so does each probe here.
std::optional<ImageSize> exrDataWindowSize(Bytes value)
{
    const std::int64_t width = std::int64_t(littleEndian32(value, 8)) - littleEndian32(value, 0) + 1;
    const std::int64_t height = std::int64_t(littleEndian32(value, 12)) - littleEndian32(value, 4) + 1;
    return sizeIfPositive(width, height);
}

std::optional<ImageSize> probeExr(Bytes b)
{
    std::optional<ImageSize> found;
    forEachExrAttribute(b, [&](std::string_view name, std::string_view, Bytes value) {
        if (name == "dataWindow" && value.size() == 16) found = exrDataWindowSize(value);
        return false;
    });
    return found;
}

} // namespace

namespace {

// The bytes OpenEXR 3.1 reads for an attribute of a known fixed-size type, whatever size the file
// declares for it (0: not a fixed-size type).
std::size_t exrFixedSize(std::string_view type)
{
    static const std::pair<std::string_view, std::size_t> sizes[] = {
        {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"double", 8}, {"envmap", 1},
        {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64},
        {"m44d", 128}, {"rational", 8}, {"tiledesc", 9}, {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16},
        {"v3i", 12}, {"v3f", 12}, {"v3d", 24}, {"deepImageState", 1}};
    for (const auto& [name, size] : sizes)
        if (name == type) return size;
    return 0;
}

// Empty when OpenEXR reads exactly `size` bytes for this attribute's value, allocating no more than
// that; otherwise what is wrong. Values of a fixed-size type, a channel list (entries up to an empty
// name), a string vector (lengths and strings), a preview (width, height, RGBA pixels).
std::string exrValueProblem(std::string_view type, Bytes value)
{
    if (const std::size_t fixed = exrFixedSize(type)) return value.size() == fixed ? "" : "is not " + std::to_string(fixed) + " bytes";
    if (type == "chlist") {
        std::size_t at = 0;
        while (at < value.size() && value[at] != 0) {
            const auto nameEnd = std::find(value.begin() + static_cast<std::ptrdiff_t>(at), value.end(), 0);
            at = static_cast<std::size_t>(nameEnd - value.begin()) + 1 + 16; // type, linear, reserved, x and y sampling
        }
        return at + 1 == value.size() ? "" : "does not end where it says";
    }
    if (type == "stringvector") {
        std::size_t at = 0;
        while (at + 4 <= value.size()) {
            const std::int32_t length = littleEndian32(value, at);
            if (length < 0 || static_cast<std::size_t>(length) > value.size() - at - 4) return "holds a string longer than itself";
            at += 4 + static_cast<std::size_t>(length);
        }
        return at == value.size() ? "" : "does not end where it says";
    }
    if (type == "preview") {
        if (value.size() < 8) return "is cut short";
        const std::uint64_t width = std::uint32_t(littleEndian32(value, 0)), height = std::uint32_t(littleEndian32(value, 4));
        return width * height * 4 == value.size() - 8 ? "" : "does not hold its declared pixels";
    }
    return {}; // strings and types OpenEXR does not know: it reads the declared size
}

// Lines per chunk of a scanline image, by compression (OpenEXR's table).
int exrLinesPerChunk(std::uint8_t compression)
{
    switch (compression) {
    case 3: case 5: return 16; // ZIP, PXR24
    case 4: case 6: case 7: case 8: return 32; // PIZ, B44, B44A, DWAA
    case 9: return 256; // DWAB
    default: return 1;
    }
}

// PNG: every chunk (length, type, data, CRC) up to IEND must fit in the file: libpng allocates
// an ancillary chunk's declared length before reading it.
std::string pngChunkProblem(Bytes b, std::uint64_t fileSize)
{
    std::size_t at = 8;
    while (at + 8 <= b.size()) {
        const std::uint64_t length = bigEndian32(b, at);
        const std::string type(b.begin() + static_cast<std::ptrdiff_t>(at) + 4, b.begin() + static_cast<std::ptrdiff_t>(at) + 8);
        if (length > 0x7FFFFFFFu || at + 12 + length > fileSize)
            return "the PNG chunk '" + type + "' declares " + std::to_string(length) + " bytes, more than the file holds";
        if (type == "IEND") return {};
        at += 12 + static_cast<std::size_t>(length);
    }
    return {};
}

} // namespace

std::string imageHeaderProblem(std::span<const std::uint8_t> b, std::uint64_t fileSize)
{
    if (startsWith(b, "\x89PNG\r\n\x1a\n")) return pngChunkProblem(b, fileSize);
    if (!startsWith(b, "\x76\x2f\x31\x01") || b.size() < 8) return {};
    // OpenEXR allocates what an attribute declares, reads some types for their own size whatever
    // the declared one, and allocates a table of every chunk's offset. So every value must be
    // exactly what OpenEXR reads, fit in the file, and the chunks' offsets too.
    const bool multipart = (b[5] & 0x10) != 0; // version flags: bit 12
    std::size_t at = 8;
    std::int64_t width = 0, height = 0, tileWidth = 0, tileHeight = 0;
    std::uint8_t compression = 3; // OpenEXR's default, ZIP
    const auto chunksProblem = [&]() -> std::string {
        if (width <= 0 || height <= 0) return {};
        const std::int64_t chunks = tileWidth > 0 && tileHeight > 0
                                        ? ((width + tileWidth - 1) / tileWidth) * ((height + tileHeight - 1) / tileHeight)
                                        : (height + exrLinesPerChunk(compression) - 1) / exrLinesPerChunk(compression);
        if (static_cast<std::uint64_t>(chunks) > fileSize / 8)
            return "the OpenEXR header declares " + std::to_string(chunks) + " chunks, more than the file can hold";
        return {};
    };
    while (at < b.size()) {
        if (b[at] == 0) { // the end of a header; a multi-part file's list of headers ends with an empty one
            if (std::string problem = chunksProblem(); !problem.empty()) return problem;
            width = height = tileWidth = tileHeight = 0;
            compression = 3;
            if (!multipart || ++at >= b.size() || b[at] == 0) return {};
            continue;
        }
        const auto nameEnd = std::find(b.begin() + static_cast<std::ptrdiff_t>(at), b.end(), 0);
        const auto typeEnd = nameEnd == b.end() ? b.end() : std::find(nameEnd + 1, b.end(), 0);
        if (typeEnd == b.end()) return {}; // cut short here: read no further
        const std::string name(b.begin() + static_cast<std::ptrdiff_t>(at), nameEnd);
        const std::string type(nameEnd + 1, typeEnd);
        const std::size_t sizeAt = static_cast<std::size_t>(typeEnd - b.begin()) + 1;
        if (sizeAt + 4 > b.size()) return {};
        const std::int64_t size = littleEndian32(b, sizeAt);
        const std::size_t dataAt = sizeAt + 4;
        const std::string attribute = "the OpenEXR attribute '" + name + "' (" + type + ")";
        if (size < 0 || static_cast<std::uint64_t>(size) > fileSize - std::min<std::uint64_t>(fileSize, dataAt))
            return attribute + " declares " + std::to_string(size) + " bytes, more than the file holds";
        if (dataAt + static_cast<std::size_t>(size) > b.size()) return {}; // beyond what was read: read no further
        const Bytes value = b.subspan(dataAt, static_cast<std::size_t>(size));
        if (std::string problem = exrValueProblem(type, value); !problem.empty()) return attribute + " " + problem;
        if (name == "dataWindow" && type == "box2i") {
            width = std::int64_t(littleEndian32(value, 8)) - littleEndian32(value, 0) + 1;
            height = std::int64_t(littleEndian32(value, 12)) - littleEndian32(value, 4) + 1;
        } else if (name == "tiles" && type == "tiledesc") {
            tileWidth = std::uint32_t(littleEndian32(value, 0));
            tileHeight = std::uint32_t(littleEndian32(value, 4));
        } else if (name == "compression" && type == "compression") {
            compression = value[0];
        }
        at = dataAt + static_cast<std::size_t>(size);
    }
    return {};
}

std::optional<ImageSize> probeImageHeader(std::span<const std::uint8_t> bytes)
{
    if (startsWith(bytes, "\x89PNG\r\n\x1a\n")) return probePng(bytes);
    if (startsWith(bytes, "\xFF\xD8")) return probeJpeg(bytes);
    if (startsWith(bytes, "#?RADIANCE") || startsWith(bytes, "#?RGBE")) return probeHdr(bytes);
    if (startsWith(bytes, "\x76\x2f\x31\x01")) return probeExr(bytes);
    return std::nullopt;
}

// "tiles" is a tiledesc (x size, y size, mode); "channels" a chlist: per channel its name, then the
// pixel type (0 uint, 1 half, 2 float), linear flag, 3 reserved bytes and the x and y sampling, up
// to an empty name. Without a compression attribute OpenEXR's default, ZIP, applies.
std::optional<ExrChunkShape> probeExrChunk(std::span<const std::uint8_t> bytes)
{
    if (!startsWith(bytes, "\x76\x2f\x31\x01")) return std::nullopt;
    std::optional<ExrChunkShape> tile;
    std::optional<ImageSize> window;
    std::uint8_t compression = 3;
    std::int64_t channels = 0;
    std::size_t widest = 0;
    forEachExrAttribute(bytes, [&](std::string_view name, std::string_view type, Bytes value) {
        if (name == "tiles" && type == "tiledesc" && value.size() >= 8)
            tile = ExrChunkShape{std::uint32_t(littleEndian32(value, 0)), std::uint32_t(littleEndian32(value, 4)), 0, 0};
        if (name == "dataWindow" && type == "box2i" && value.size() == 16) window = exrDataWindowSize(value);
        if (name == "compression" && type == "compression" && value.size() == 1) compression = value[0];
        if (name == "channels" && type == "chlist") {
            channels = 0;
            widest = 0;
            for (std::size_t at = 0; at < value.size() && value[at] != 0;) {
                const auto nameEnd = std::find(value.begin() + static_cast<std::ptrdiff_t>(at), value.end(), 0);
                const std::size_t typeAt = static_cast<std::size_t>(nameEnd - value.begin()) + 1;
                if (typeAt + 16 > value.size()) break;
                ++channels;
                widest = std::max<std::size_t>(widest, littleEndian32(value, typeAt) == 1 ? 2 : 4);
                at = typeAt + 16;
            }
        }
        return false;
    });
    std::optional<ExrChunkShape> chunk = tile;
    if (!chunk && window) chunk = ExrChunkShape{window->width, exrLinesPerChunk(compression), 0, 0};
    if (chunk) {
        chunk->channels = channels;
        chunk->bytesPerValue = widest;
    }
    return chunk;
}

} // namespace glint
