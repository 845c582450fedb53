#include "gltf_accessors.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace glint::test {

namespace {

std::vector<std::uint8_t> readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + file.string());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int componentsOf(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    throw std::runtime_error("unsupported accessor type " + type);
}

int bytesOf(int componentType) {
    switch (componentType) {
    case 5121: return 1;
    case 5123: return 2;
    case 5125:
    case 5126: return 4;
    default: throw std::runtime_error("unsupported component type");
    }
}

// Calls read(elementStart, component) for every component of every element.
template <class Read>
void forEachComponent(const GltfDocument& doc, int index, Read read) {
    const nlohmann::json& accessor = doc.json.at("accessors").at(index);
    const nlohmann::json& view = doc.json.at("bufferViews").at(accessor.at("bufferView").get<int>());
    const std::vector<std::uint8_t>& buffer = doc.buffers.at(view.at("buffer").get<std::size_t>());
    const int components = componentsOf(accessor.at("type"));
    const int componentBytes = bytesOf(accessor.at("componentType"));
    const std::size_t stride = view.value("byteStride", std::size_t(components * componentBytes));
    const std::size_t start = view.value("byteOffset", std::size_t(0)) + accessor.value("byteOffset", std::size_t(0));
    const std::size_t count = accessor.at("count");
    if (start + (count - 1) * stride + std::size_t(components * componentBytes) > buffer.size())
        throw std::runtime_error("accessor past the end of its buffer");
    for (std::size_t e = 0; e < count; ++e)
        for (int c = 0; c < components; ++c) read(buffer.data() + start + e * stride + std::size_t(c * componentBytes));
}

} // namespace

GltfDocument readGltf(const std::filesystem::path& file) {
    GltfDocument doc;
    doc.folder = file.parent_path();
    const std::vector<std::uint8_t> text = readBytes(file);
    doc.json = nlohmann::json::parse(text.begin(), text.end());
    for (const nlohmann::json& buffer : doc.json.at("buffers"))
        doc.buffers.push_back(readBytes(doc.folder / buffer.at("uri").get<std::string>()));
    return doc;
}

std::vector<float> readFloats(const GltfDocument& doc, int accessor) {
    if (doc.json.at("accessors").at(accessor).at("componentType") != 5126)
        throw std::runtime_error("not a float accessor");
    std::vector<float> values;
    forEachComponent(doc, accessor, [&](const std::uint8_t* bytes) {
        float v;
        std::memcpy(&v, bytes, sizeof v);
        values.push_back(v);
    });
    return values;
}

std::vector<std::uint32_t> readIndices(const GltfDocument& doc, int accessor) {
    const int componentType = doc.json.at("accessors").at(accessor).at("componentType");
    std::vector<std::uint32_t> values;
    forEachComponent(doc, accessor, [&](const std::uint8_t* bytes) {
        std::uint32_t v = 0;
        if (componentType == 5121) v = bytes[0];
        if (componentType == 5123) v = std::uint32_t(bytes[0] | (bytes[1] << 8));
        if (componentType == 5125) std::memcpy(&v, bytes, sizeof v);
        values.push_back(v);
    });
    return values;
}

} // namespace glint::test
