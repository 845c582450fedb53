#pragma once
// The binary side of a glTF being written: one buffer, laid out in the order things are added
// (the writer adds them in id order), every bufferView starting on a 4-byte boundary.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace glint {

enum class ViewTarget { None = 0, Vertices = 34962, Indices = 34963 };

class GltfBufferBuilder {
public:
    // Returns the accessor index. Float accessors; `withBounds` adds min/max per component
    // (required for POSITION and animation inputs).
    int addFloatAccessor(std::span<const float> values, int components, ViewTarget target, bool withBounds);
    // Triangle indices as uint16 when every index fits below 65535 (the restart value), else uint32.
    int addIndexAccessor(std::span<const std::uint32_t> indices);
    // Raw bytes (an embedded image): returns the bufferView index.
    int addBytesView(std::span<const std::uint8_t> bytes);

    const std::vector<std::uint8_t>& bytes() const { return bytes_; }
    nlohmann::json& accessors() { return accessors_; }
    nlohmann::json& bufferViews() { return bufferViews_; }

private:
    int addView(std::span<const std::uint8_t> bytes, ViewTarget target);

    std::vector<std::uint8_t> bytes_;
    nlohmann::json accessors_ = nlohmann::json::array();
    nlohmann::json bufferViews_ = nlohmann::json::array();
};

} // namespace glint
