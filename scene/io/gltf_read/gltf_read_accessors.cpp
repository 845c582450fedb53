#include "gltf_read_accessors.h"

#include <algorithm>
#include <cstring>

namespace glint {

namespace {

struct ElementLayout {
    int componentType = 0;
    int components = 0;
    std::size_t componentSize = 0;
    bool normalized = false;
};

template <class T>
T load(const std::uint8_t* p)
{
    T value;
    std::memcpy(&value, p, sizeof(T));
    return value;
}

// glTF's normalized integer rules: signed values clamp at -1.
double componentValue(const std::uint8_t* p, int componentType, bool normalized)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return normalized ? std::max(load<std::int8_t>(p) / 127.0, -1.0) : load<std::int8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? load<std::uint8_t>(p) / 255.0 : load<std::uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return normalized ? std::max(load<std::int16_t>(p) / 32767.0, -1.0) : load<std::int16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return normalized ? load<std::uint16_t>(p) / 65535.0 : load<std::uint16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return normalized ? load<std::uint32_t>(p) / 4294967295.0 : load<std::uint32_t>(p);
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
    default: return 0.0;
    }
}

// The bytes of one bufferView, checked against the loaded buffer.
std::span<const std::uint8_t> viewBytes(const GltfReadContext& ctx, int view, const std::string& what)
{
    if (view < 0 || static_cast<std::size_t>(view) >= ctx.model.bufferViews.size()) ctx.fail("dangling-index", what + " names a missing bufferView");
    const tinygltf::BufferView& v = ctx.model.bufferViews[static_cast<std::size_t>(view)];
    if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= ctx.model.buffers.size()) ctx.fail("dangling-index", what + " names a missing buffer");
    const std::vector<unsigned char>& data = ctx.model.buffers[static_cast<std::size_t>(v.buffer)].data;
    if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
        ctx.fail("buffer-too-short", "bufferView " + std::to_string(view) + " lies past the end of buffer " + std::to_string(v.buffer) + " (" + std::to_string(data.size()) + " bytes)");
    return {data.data() + v.byteOffset, v.byteLength};
}

// `count` elements of `layout`, from `offset` with `stride`, into out[i * components + c] (or at `slots`).
void readElements(const GltfReadContext& ctx, std::span<const std::uint8_t> bytes, std::size_t offset, std::size_t stride,
                  const ElementLayout& layout, std::size_t count, const std::string& what, std::vector<double>& out)
{
    const std::size_t elementSize = layout.componentSize * static_cast<std::size_t>(layout.components);
    const std::size_t step = stride ? stride : elementSize;
    if (count > 0 && (offset > bytes.size() || (count - 1) > (bytes.size() - offset) / step || offset + (count - 1) * step + elementSize > bytes.size()))
        ctx.fail("accessor-out-of-range", what + " reads past the end of its bufferView (" + std::to_string(bytes.size()) + " bytes)");
    out.resize(count * static_cast<std::size_t>(layout.components));
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < layout.components; ++c)
            out[i * static_cast<std::size_t>(layout.components) + static_cast<std::size_t>(c)] =
                componentValue(bytes.data() + offset + i * step + static_cast<std::size_t>(c) * layout.componentSize, layout.componentType, layout.normalized);
}

const tinygltf::Accessor& accessorAt(const GltfReadContext& ctx, int accessor, const std::string& what)
{
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= ctx.model.accessors.size()) ctx.fail("dangling-index", what + " names a missing accessor");
    return ctx.model.accessors[static_cast<std::size_t>(accessor)];
}

void applySparse(const GltfReadContext& ctx, const tinygltf::Accessor& a, const ElementLayout& layout, const std::string& what, std::vector<double>& out)
{
    const std::size_t count = static_cast<std::size_t>(a.sparse.count);
    const ElementLayout indexLayout{a.sparse.indices.componentType, 1, static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.sparse.indices.componentType))), false};
    std::vector<double> indices;
    std::vector<double> values;
    readElements(ctx, viewBytes(ctx, a.sparse.indices.bufferView, what), a.sparse.indices.byteOffset, 0, indexLayout, count, what + " (sparse indices)", indices);
    readElements(ctx, viewBytes(ctx, a.sparse.values.bufferView, what), a.sparse.values.byteOffset, 0, layout, count, what + " (sparse values)", values);
    const auto n = static_cast<std::size_t>(layout.components);
    for (std::size_t i = 0; i < count; ++i) {
        const auto target = static_cast<std::size_t>(indices[i]);
        if (target >= a.count) ctx.fail("index-out-of-range", what + ": sparse index " + std::to_string(target) + " is past the accessor's " + std::to_string(a.count) + " elements");
        std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(i * n), n, out.begin() + static_cast<std::ptrdiff_t>(target * n));
    }
}

std::vector<double> readAccessor(const GltfReadContext& ctx, const tinygltf::Accessor& a, const std::string& what)
{
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    const int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (components <= 0 || componentSize <= 0) ctx.fail("invalid-gltf", what + " has an unknown component type");
    const ElementLayout layout{a.componentType, components, static_cast<std::size_t>(componentSize), a.normalized};
    std::vector<double> out;
    if (a.bufferView >= 0) {
        const auto& view = ctx.model.bufferViews[static_cast<std::size_t>(a.bufferView)];
        readElements(ctx, viewBytes(ctx, a.bufferView, what), a.byteOffset, view.byteStride, layout, a.count, what, out);
    } else {
        out.assign(a.count * static_cast<std::size_t>(components), 0.0); // count was capped by validation
    }
    if (a.sparse.isSparse) applySparse(ctx, a, layout, what, out);
    return out;
}

} // namespace

AccessorValues readAccessorFloats(const GltfReadContext& ctx, int accessor, int expectedComponents, const std::string& what)
{
    const tinygltf::Accessor& a = accessorAt(ctx, accessor, what);
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (expectedComponents > 0 && components != expectedComponents)
        ctx.fail("wrong-type", what + " (accessor " + std::to_string(accessor) + ") has " + std::to_string(components) + " components per element, expected " + std::to_string(expectedComponents));
    const std::vector<double> values = readAccessor(ctx, a, what);
    AccessorValues out{a.count, components, std::vector<float>(values.size())};
    std::transform(values.begin(), values.end(), out.values.begin(), [](double v) { return static_cast<float>(v); });
    return out;
}

std::vector<std::uint32_t> readAccessorIndices(const GltfReadContext& ctx, int accessor, const std::string& what)
{
    const tinygltf::Accessor& a = accessorAt(ctx, accessor, what);
    const bool unsignedInteger = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                 a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    if (a.type != TINYGLTF_TYPE_SCALAR || !unsignedInteger || a.normalized)
        ctx.fail("wrong-type", what + " (accessor " + std::to_string(accessor) + ") must be unsigned integer scalars");
    const std::vector<double> values = readAccessor(ctx, a, what);
    std::vector<std::uint32_t> out(values.size());
    std::transform(values.begin(), values.end(), out.begin(), [](double v) { return static_cast<std::uint32_t>(v); });
    return out;
}

} // namespace glint
