// GLB container checks and the depth-capped JSON parse. Nothing here trusts a length field: every
// chunk is checked against the bytes actually present before it is used.
#include "gltf_reader.h"
#include "scene/io/json/json_parse.h"

#include <algorithm>
#include <cstdio>

namespace glint {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;     // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;    // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;     // "BIN\0"

std::uint32_t littleEndian32(std::span<const std::uint8_t> b, std::size_t at)
{
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 | std::uint32_t(b[at + 3]) << 24;
}

struct Chunk {
    std::uint32_t type = 0;
    std::span<const std::uint8_t> data;
};

Chunk readChunk(std::span<const std::uint8_t> glb, std::size_t at, const std::string& file, const char* which)
{
    if (at + 8 > glb.size())
        throw FileError(file, "truncated-glb", std::string("the GLB ends inside the header of its ") + which + " chunk");
    const std::uint64_t length = littleEndian32(glb, at);
    if (at + 8 + length > glb.size())
        throw FileError(file, "glb-chunk-out-of-range", std::string("the GLB's ") + which + " chunk claims " + std::to_string(length) +
                                                           " bytes, but only " + std::to_string(glb.size() - at - 8) + " follow");
    return {littleEndian32(glb, at + 4), glb.subspan(at + 8, length)};
}

GltfSource splitGlb(std::span<const std::uint8_t> bytes, const std::string& file)
{
    if (bytes.size() < 12) throw FileError(file, "truncated-glb", "the GLB header is cut short (" + std::to_string(bytes.size()) + " of 12 bytes)");
    if (littleEndian32(bytes, 4) != 2) throw FileError(file, "invalid-glb", "GLB version " + std::to_string(littleEndian32(bytes, 4)) + " (Glint reads version 2)");
    const std::uint64_t declared = littleEndian32(bytes, 8);
    if (declared > bytes.size())
        throw FileError(file, "truncated-glb", "the GLB header declares " + std::to_string(declared) + " bytes, but the file has " + std::to_string(bytes.size()));
    const auto glb = bytes.first(declared);
    const Chunk json = readChunk(glb, 12, file, "JSON");
    if (json.type != kChunkJson) throw FileError(file, "invalid-glb", "the GLB's first chunk is not JSON");
    GltfSource source{{reinterpret_cast<const char*>(json.data.data()), json.data.size()}, std::nullopt, true};
    const std::size_t next = 20 + ((json.data.size() + 3) & ~std::size_t(3));
    if (next + 8 <= glb.size()) {
        const Chunk bin = readChunk(glb, next, file, "BIN");
        if (bin.type == kChunkBin) source.bin = bin.data;
    } else if (next < glb.size() && next + 8 > glb.size()) {
        throw FileError(file, "truncated-glb", "the GLB ends inside the header of its BIN chunk");
    }
    return source;
}

// Depth of [ and { outside strings, so a hostile file cannot drive a recursive parser off the stack.
int jsonNestingDepth(std::string_view text, int limit)
{
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) return depth;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return depth;
}

// The offset of the first byte that cannot begin a JSON text (a control byte other than
// whitespace, or one outside ASCII that is not a UTF-8 byte order mark), or npos.
std::size_t firstBinaryByte(std::span<const std::uint8_t> bytes)
{
    std::size_t at = 0;
    if (bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF) at = 3;
    for (; at < bytes.size(); ++at) {
        const std::uint8_t b = bytes[at];
        if (b == ' ' || b == '\t' || b == '\n' || b == '\r') continue;
        return b < 0x20 || b >= 0x7F ? at : std::string::npos;
    }
    return std::string::npos;
}

} // namespace

GltfSource splitGltfContainer(std::span<const std::uint8_t> bytes, const std::string& file)
{
    if (bytes.empty()) throw FileError(file, "empty-file", "the file is empty");
    if (bytes.size() >= 4 && littleEndian32(bytes, 0) == kGlbMagic) return splitGlb(bytes, file);
    // Content decides the container, not the extension (a GLB named .gltf loads); bytes that are
    // neither say so, where the JSON parser would report a syntax error at line 1.
    if (const std::size_t at = firstBinaryByte(bytes); at != std::string::npos) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02X", bytes[at]);
        throw FileError(file, "not-gltf", std::string("not a glTF file: no binary glTF header ('glTF'), and byte ") + std::to_string(at) +
                                              " (" + hex + ") cannot begin glTF's JSON");
    }
    return {{reinterpret_cast<const char*>(bytes.data()), bytes.size()}, std::nullopt, false};
}

nlohmann::json parseGltfJson(std::string_view text, const std::string& file, int maxDepth)
{
    if (jsonNestingDepth(text, maxDepth) > maxDepth)
        throw FileError(file, "json-too-deep", "the JSON nests deeper than " + std::to_string(maxDepth) + " levels");
    const nlohmann::json doc = parseJsonText(text, file, maxDepth);
    if (!doc.is_object()) throw FileError(file, "wrong-type", "the glTF's top level must be a JSON object");
    return doc;
}

} // namespace glint
