// Byte-level checks before tinygltf loads anything: every buffer exists, is no shorter than it
// declares and no larger than the cap; every bufferView lies inside its buffer; every accessor
// (and its sparse parts) inside its bufferView. Counts are checked before any multiplication can
// overflow and before anything is allocated.
#include "gltf_read_json.h"
#include "gltf_read_uri.h"
#include "gltf_reader.h"
#include "scene/io/files/confined_fs.h"

#include <array>
#include <filesystem>

namespace glint {

namespace {

constexpr std::array kHonouredExtensions = {"KHR_materials_emissive_strength", "KHR_materials_specular", "KHR_materials_transmission",
                                            "KHR_materials_ior", "KHR_materials_volume", "KHR_texture_transform",
                                            "KHR_lights_punctual", "KHR_mesh_quantization"};

struct DataChecker {
    const Json& doc;
    const GltfSource& source;
    const ConfinedFolder& folder;
    const std::string& file;
    const LoadOptions& options;
    JsonReader json{file};
    std::vector<std::uint64_t> bufferLengths{};
    std::vector<std::uint64_t> viewLengths{};

    const Json& items(const char* key) const
    {
        static const Json empty = Json::array();
        const Json* value = json.member(doc, key);
        return value ? *value : empty;
    }

    [[noreturn]] void fail(const char* code, const std::string& message) const { throw FileError(file, code, message); }

    void checkRequiredExtensions() const
    {
        const Json* required = json.member(doc, "extensionsRequired");
        if (!required) return;
        if (!required->is_array()) fail("wrong-type", "extensionsRequired must be an array of strings");
        for (const Json& name : *required) {
            if (!name.is_string()) fail("wrong-type", "extensionsRequired must be an array of strings");
            const auto& n = name.get_ref<const std::string&>();
            if (std::find(kHonouredExtensions.begin(), kHonouredExtensions.end(), n) == kHonouredExtensions.end())
                fail("unsupported-required-extension", "the file requires the extension " + n + ", which Glint cannot read");
        }
    }

    std::uint64_t availableBytes(const Json& buffer, std::size_t index) const
    {
        const std::string where = "buffers[" + std::to_string(index) + "]";
        const std::string uri = json.string(buffer, "uri", where);
        if (uri.empty()) {
            if (!source.glb || index != 0) fail("invalid-gltf", where + " has no uri (only a GLB's first buffer may omit it)");
            if (!source.bin) fail("buffer-too-short", where + " refers to the GLB's BIN chunk, but the GLB has none");
            return source.bin->size();
        }
        if (isDataUri(uri)) {
            auto data = parseDataUri(uri);
            if (!data) fail("malformed-data-uri", where + ".uri is a data: URI that is not valid base64 (\"data:<type>;base64,...\")");
            return data->bytes.size();
        }
        const std::filesystem::path path = confinedPath(folder, percentDecoded(uri), file);
        std::error_code error;
        const auto size = std::filesystem::file_size(path, error);
        if (error) fail("missing-file", where + " names '" + uri + "', which cannot be read: " + error.message());
        return size;
    }

    void checkBuffers()
    {
        const Json& buffers = items("buffers");
        for (std::size_t i = 0; i < buffers.size(); ++i) {
            const std::string where = "buffers[" + std::to_string(i) + "]";
            if (!json.member(buffers[i], "byteLength")) fail("wrong-type", where + ".byteLength is missing");
            const std::uint64_t declared = json.unsignedNumber(buffers[i], "byteLength", 0, where);
            if (declared > options.maxBufferBytes)
                fail("buffer-too-large", where + " declares " + std::to_string(declared) + " bytes, more than the limit of " + std::to_string(options.maxBufferBytes));
            const std::uint64_t available = availableBytes(buffers[i], i);
            if (available < declared)
                fail("buffer-too-short", where + " declares " + std::to_string(declared) + " bytes, but its data holds only " + std::to_string(available));
            bufferLengths.push_back(declared);
        }
    }

    void checkBufferViews()
    {
        const Json& views = items("bufferViews");
        for (std::size_t i = 0; i < views.size(); ++i) {
            const std::string where = "bufferViews[" + std::to_string(i) + "]";
            const std::uint64_t offset = json.unsignedNumber(views[i], "byteOffset", 0, where);
            const std::uint64_t length = json.unsignedNumber(views[i], "byteLength", 0, where);
            const std::uint64_t stride = json.unsignedNumber(views[i], "byteStride", 0, where);
            if (stride != 0 && (stride < 4 || stride > 252 || stride % 4 != 0)) fail("invalid-gltf", where + ".byteStride is " + std::to_string(stride) + " (4..252, a multiple of 4)");
            const int buffer = json.index(views[i], "buffer", where);
            if (buffer < 0) fail("wrong-type", where + ".buffer is missing");
            const std::uint64_t bufferLength = bufferLengths[static_cast<std::size_t>(buffer)];
            if (offset > bufferLength || length > bufferLength - offset)
                fail("buffer-view-out-of-range", where + " covers bytes " + std::to_string(offset) + ".." + std::to_string(offset + length) +
                                                      ", past the end of buffer " + std::to_string(buffer) + " (" + std::to_string(bufferLength) + " bytes)");
            viewLengths.push_back(length);
        }
    }

    void checkImages() const
    {
        const Json& images = items("images");
        for (std::size_t i = 0; i < images.size(); ++i) {
            const std::string where = "images[" + std::to_string(i) + "]";
            const std::string uri = json.string(images[i], "uri", where);
            if (uri.empty()) continue;
            if (isDataUri(uri)) {
                if (!parseDataUri(uri)) fail("malformed-data-uri", where + ".uri is a data: URI that is not valid base64 (\"data:<type>;base64,...\")");
            } else {
                confinedPath(folder, percentDecoded(uri), file);
            }
        }
    }

    void checkRange(std::uint64_t offset, std::uint64_t count, std::uint64_t elementSize, std::uint64_t stride, int view, const std::string& what) const
    {
        if (view < 0) fail("invalid-gltf", what + " has no bufferView");
        const std::uint64_t viewLength = viewLengths[static_cast<std::size_t>(view)];
        const std::uint64_t step = stride ? stride : elementSize;
        // count <= maxBufferBytes (checked by the caller), so these products cannot overflow.
        const std::uint64_t end = offset + step * (count - 1) + elementSize;
        if (end > viewLength)
            fail("accessor-out-of-range", what + " reads " + std::to_string(end - viewLength) + " bytes past the end of bufferView " +
                                              std::to_string(view) + " (" + std::to_string(viewLength) + " bytes)");
    }

    void checkAccessors() const;
};

std::uint64_t componentSize(std::uint64_t componentType)
{
    switch (componentType) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
    }
}

std::uint64_t componentCount(const std::string& type)
{
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4" || type == "MAT2") return 4;
    if (type == "MAT3") return 9;
    if (type == "MAT4") return 16;
    return 0;
}

std::uint64_t strideOf(const JsonReader& json, const Json& doc, int view)
{
    if (view < 0) return 0;
    return json.unsignedNumber(doc["bufferViews"][static_cast<std::size_t>(view)], "byteStride", 0, "bufferViews[" + std::to_string(view) + "]");
}

void DataChecker::checkAccessors() const
{
    const Json& accessors = items("accessors");
    for (std::size_t i = 0; i < accessors.size(); ++i) {
        const Json& a = accessors[i];
        const std::string where = "accessors[" + std::to_string(i) + "]";
        const std::uint64_t size = componentSize(json.unsignedNumber(a, "componentType", 0, where)) * componentCount(json.string(a, "type", where));
        if (size == 0) fail("invalid-gltf", where + " has an unknown componentType or type");
        const std::uint64_t count = json.unsignedNumber(a, "count", 0, where);
        if (count == 0) fail("invalid-gltf", where + ".count must be at least 1");
        if (count > options.maxBufferBytes / size)
            fail("huge-count", where + ".count is " + std::to_string(count) + ": more than " + std::to_string(options.maxBufferBytes) + " bytes of data");
        const int view = json.index(a, "bufferView", where);
        // Without a bufferView nothing in the file bounds the zeros the reader would allocate.
        if (view < 0 && count * componentCount(json.string(a, "type", where)) > options.maxBufferBytes / 16)
            fail("huge-count", where + ".count is " + std::to_string(count) + " with no bufferView: too many elements to fill with zeros");
        if (view >= 0) checkRange(json.unsignedNumber(a, "byteOffset", 0, where), count, size, strideOf(json, doc, view), view, "accessor " + std::to_string(i));
        const Json* sparse = json.member(a, "sparse");
        if (!sparse) continue;
        const std::uint64_t sparseCount = json.unsignedNumber(*sparse, "count", 0, where + ".sparse");
        if (sparseCount == 0 || sparseCount > count) fail("invalid-gltf", where + ".sparse.count must be 1.." + std::to_string(count));
        const Json* indices = json.member(*sparse, "indices");
        const Json* values = json.member(*sparse, "values");
        if (!indices || !values || !indices->is_object() || !values->is_object()) fail("wrong-type", where + ".sparse needs indices and values objects");
        const std::uint64_t indexSize = componentSize(json.unsignedNumber(*indices, "componentType", 0, where + ".sparse.indices"));
        if (indexSize == 0) fail("invalid-gltf", where + ".sparse.indices has an unknown componentType");
        checkRange(json.unsignedNumber(*indices, "byteOffset", 0, where), sparseCount, indexSize, 0, json.index(*indices, "bufferView", where + ".sparse.indices"), "the sparse indices of accessor " + std::to_string(i));
        checkRange(json.unsignedNumber(*values, "byteOffset", 0, where), sparseCount, size, 0, json.index(*values, "bufferView", where + ".sparse.values"), "the sparse values of accessor " + std::to_string(i));
    }
}

} // namespace

void validateGltfData(const nlohmann::json& doc, const GltfSource& source, const ConfinedFolder& folder, const std::string& file, const LoadOptions& options)
{
    DataChecker checker{doc, source, folder, file, options};
    checker.checkRequiredExtensions();
    checker.checkBuffers();
    checker.checkBufferViews();
    checker.checkAccessors();
    checker.checkImages();
}

} // namespace glint
