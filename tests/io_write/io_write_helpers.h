#pragma once
// Small helpers the writer's suites share.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace glint::test {

inline std::vector<std::uint8_t> readBytes(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline std::string readText(const std::filesystem::path& file)
{
    const auto bytes = readBytes(file);
    return {bytes.begin(), bytes.end()};
}

// The JSON chunk of a GLB (header 12 bytes, then chunk length, chunk type, data).
inline nlohmann::json glbJson(const std::vector<std::uint8_t>& glb)
{
    const auto length = static_cast<std::size_t>(glb.at(12)) | static_cast<std::size_t>(glb.at(13)) << 8 |
                        static_cast<std::size_t>(glb.at(14)) << 16 | static_cast<std::size_t>(glb.at(15)) << 24;
    return nlohmann::json::parse(glb.begin() + 20, glb.begin() + 20 + static_cast<std::ptrdiff_t>(length));
}

// Every file of a folder, recursively, relative to it, sorted.
inline std::vector<std::string> listFiles(const std::filesystem::path& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) names.push_back(std::filesystem::relative(entry.path(), folder).string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace glint::test
