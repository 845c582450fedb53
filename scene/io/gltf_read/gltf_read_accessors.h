#pragma once
// Reading accessor data from a loaded tinygltf model, every read bounds-checked against the bytes
// actually present (the document was validated against its declared sizes before loading).
// Normalized integers become floats as glTF defines; sparse substitutions are applied.
#include "gltf_reader.h"

#include <cstdint>
#include <vector>

namespace glint {

struct AccessorValues {
    std::size_t count = 0;
    int components = 0;
    std::vector<float> values; // count * components
};

// `expectedComponents` is checked (0: any); `what` names the use in errors ("POSITION of mesh 2").
AccessorValues readAccessorFloats(const GltfReadContext& ctx, int accessor, int expectedComponents, const std::string& what);

// A scalar integer accessor (indices) read exactly (no float rounding).
std::vector<std::uint32_t> readAccessorIndices(const GltfReadContext& ctx, int accessor, const std::string& what);

} // namespace glint
