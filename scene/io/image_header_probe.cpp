// Image dimensions from header bytes. Each format's probe reads only what its header promises and
// checks every offset against the buffer, so truncated or hostile headers give "unknown", never a read
// past the end.
#include "image_decoder.h"

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

// Walk the marker segments to the first start-of-frame: precision, height, width.
std::optional<ImageSize> probeJpeg(Bytes b)
{
    std::size_t at = 2;
    while (at + 4 <= b.size()) {
        if (b[at] != 0xFF) return std::nullopt;
        const std::uint8_t marker = b[at + 1];
        if (marker == 0xFF) { ++at; continue; } // fill byte
        const std::size_t length = bigEndian16(b, at + 2);
        if (isStartOfFrame(marker)) {
            if (at + 9 > b.size()) return std::nullopt;
            return sizeIfPositive(bigEndian16(b, at + 7), bigEndian16(b, at + 5));
        }
        if (length < 2) return std::nullopt;
        at += 2 + length;
    }
    return std::nullopt;
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

// Attributes (name\0 type\0 size data) up to an empty name; dataWindow is a box2i (xMin yMin xMax yMax).
std::optional<ImageSize> probeExr(Bytes b)
{
    std::size_t at = 8;
    while (at < b.size() && b[at] != 0) {
        const auto nameEnd = std::find(b.begin() + static_cast<std::ptrdiff_t>(at), b.end(), 0);
        const auto typeEnd = nameEnd == b.end() ? b.end() : std::find(nameEnd + 1, b.end(), 0);
        if (typeEnd == b.end()) return std::nullopt;
        const std::string name(b.begin() + static_cast<std::ptrdiff_t>(at), nameEnd);
        const std::size_t sizeAt = static_cast<std::size_t>(typeEnd - b.begin()) + 1;
        if (sizeAt + 4 > b.size()) return std::nullopt;
        const std::int64_t size = littleEndian32(b, sizeAt);
        const std::size_t dataAt = sizeAt + 4;
        if (size < 0 || dataAt + static_cast<std::size_t>(size) > b.size()) return std::nullopt;
        if (name == "dataWindow" && size == 16) {
            const std::int64_t width = std::int64_t(littleEndian32(b, dataAt + 8)) - littleEndian32(b, dataAt) + 1;
            const std::int64_t height = std::int64_t(littleEndian32(b, dataAt + 12)) - littleEndian32(b, dataAt + 4) + 1;
            return sizeIfPositive(width, height);
        }
        at = dataAt + static_cast<std::size_t>(size);
    }
    return std::nullopt;
}

} // namespace

std::optional<ImageSize> probeImageHeader(std::span<const std::uint8_t> bytes)
{
    if (startsWith(bytes, "\x89PNG\r\n\x1a\n")) return probePng(bytes);
    if (startsWith(bytes, "\xFF\xD8")) return probeJpeg(bytes);
    if (startsWith(bytes, "#?RADIANCE") || startsWith(bytes, "#?RGBE")) return probeHdr(bytes);
    if (startsWith(bytes, "\x76\x2f\x31\x01")) return probeExr(bytes);
    return std::nullopt;
}

} // namespace glint
