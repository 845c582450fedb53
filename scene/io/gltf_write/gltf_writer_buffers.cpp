#include "gltf_writer_buffers.h"

#include "scene/io/json/json_numbers.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace glint {

namespace {

constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr std::uint32_t kShortRestart = 65535;

const char* accessorType(int components)
{
    switch (components) {
    case 1: return "SCALAR";
    case 2: return "VEC2";
    case 3: return "VEC3";
    default: return "VEC4";
    }
}

template <class T>
std::span<const std::uint8_t> asBytes(std::span<const T> values)
{
    return {reinterpret_cast<const std::uint8_t*>(values.data()), values.size_bytes()};
}

void addBounds(nlohmann::json& accessor, std::span<const float> values, int components)
{
    std::vector<float> low(components, std::numeric_limits<float>::max());
    std::vector<float> high(components, std::numeric_limits<float>::lowest());
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto c = i % static_cast<std::size_t>(components);
        low[c] = std::min(low[c], values[i]);
        high[c] = std::max(high[c], values[i]);
    }
    accessor["min"] = jsonFloats(low);
    accessor["max"] = jsonFloats(high);
}

} // namespace

int GltfBufferBuilder::addView(std::span<const std::uint8_t> bytes, ViewTarget target)
{
    const std::size_t offset = bytes_.size();
    bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
    bytes_.resize((bytes_.size() + 3) & ~std::size_t{3}, 0);
    nlohmann::json view{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size()}};
    if (target != ViewTarget::None) view["target"] = static_cast<int>(target);
    bufferViews_.push_back(std::move(view));
    return static_cast<int>(bufferViews_.size()) - 1;
}

int GltfBufferBuilder::addBytesView(std::span<const std::uint8_t> bytes)
{
    return addView(bytes, ViewTarget::None);
}

int GltfBufferBuilder::addFloatAccessor(std::span<const float> values, int components, ViewTarget target,
                                        bool withBounds)
{
    nlohmann::json accessor{{"bufferView", addView(asBytes(values), target)},
                            {"componentType", kFloat},
                            {"count", values.size() / static_cast<std::size_t>(components)},
                            {"type", accessorType(components)}};
    if (withBounds) addBounds(accessor, values, components);
    accessors_.push_back(std::move(accessor));
    return static_cast<int>(accessors_.size()) - 1;
}

int GltfBufferBuilder::addIndexAccessor(std::span<const std::uint32_t> indices)
{
    const bool fitsShort = std::all_of(indices.begin(), indices.end(), [](std::uint32_t i) { return i < kShortRestart; });
    int view = 0;
    if (fitsShort) {
        const std::vector<std::uint16_t> shorts(indices.begin(), indices.end());
        view = addView(asBytes(std::span<const std::uint16_t>(shorts)), ViewTarget::Indices);
    } else {
        view = addView(asBytes(indices), ViewTarget::Indices);
    }
    accessors_.push_back({{"bufferView", view},
                          {"componentType", fitsShort ? kUnsignedShort : kUnsignedInt},
                          {"count", indices.size()},
                          {"type", "SCALAR"}});
    return static_cast<int>(accessors_.size()) - 1;
}

} // namespace glint
