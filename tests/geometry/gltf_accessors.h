#pragma once
// A minimal reader for the few glTF accessors the geometry tests need (tightly typed float and
// unsigned index data in external .bin buffers), so they do not depend on the real loader.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace glint::test {

struct GltfDocument {
    std::filesystem::path folder;
    nlohmann::json json;
    std::vector<std::vector<std::uint8_t>> buffers;
};

GltfDocument readGltf(const std::filesystem::path& file);
// A float accessor: every component of every element, packed.
std::vector<float> readFloats(const GltfDocument& doc, int accessor);
// Index accessor (unsigned byte, short or int).
std::vector<std::uint32_t> readIndices(const GltfDocument& doc, int accessor);

} // namespace glint::test
