// The binary glTF container (glTF 2.0 spec, "GLB File Format Specification").
#include "gltf_writer.h"

namespace glint {

namespace {

constexpr std::uint32_t kMagic = 0x46546C67;     // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A; // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;  // "BIN\0"

void appendU32(std::vector<std::uint8_t>& out, std::uint32_t v)
{
    for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

std::size_t padded(std::size_t n) { return (n + 3) & ~std::size_t{3}; }

void appendChunk(std::vector<std::uint8_t>& out, std::uint32_t type, const std::uint8_t* data, std::size_t size, std::uint8_t pad)
{
    appendU32(out, static_cast<std::uint32_t>(padded(size)));
    appendU32(out, type);
    out.insert(out.end(), data, data + size);
    out.resize(out.size() + padded(size) - size, pad);
}

} // namespace

std::vector<std::uint8_t> glbBytes(const GltfOutput& output)
{
    std::vector<std::uint8_t> out;
    out.reserve(12 + 8 + padded(output.json.size()) + 8 + padded(output.bin.size()));
    appendU32(out, kMagic);
    appendU32(out, 2);
    appendU32(out, 0); // total length, patched below
    appendChunk(out, kJsonChunk, reinterpret_cast<const std::uint8_t*>(output.json.data()), output.json.size(), ' ');
    if (!output.bin.empty()) appendChunk(out, kBinChunk, output.bin.data(), output.bin.size(), 0);
    const auto total = static_cast<std::uint32_t>(out.size());
    for (int i = 0; i < 4; ++i) out[8 + i] = static_cast<std::uint8_t>(total >> (8 * i));
    return out;
}

} // namespace glint
