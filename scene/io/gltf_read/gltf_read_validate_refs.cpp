// Before tinygltf or the converter look at anything: the top-level arrays are arrays of objects and
// every index points into the array it names. tinygltf itself indexes some of these unchecked.
#include "gltf_reader.h"

#include <string_view>

namespace glint {

namespace {

using Json = nlohmann::json;

// `path` walks from an item of `collection`: "a/b" members, "*" every element or value.
// `target` is a top-level array, or "@samplers" for the same animation's samplers.
struct Reference {
    const char* collection;
    const char* path;
    const char* target;
};

constexpr Reference kReferences[] = {
    {"scenes", "nodes/*", "nodes"},
    {"nodes", "children/*", "nodes"},
    {"nodes", "mesh", "meshes"},
    {"nodes", "camera", "cameras"},
    {"nodes", "skin", "skins"},
    {"nodes", "extensions/KHR_lights_punctual/light", "extensions/KHR_lights_punctual/lights"},
    {"nodes", "extensions/GLINT_shape/material", "materials"},
    {"meshes", "primitives/*/attributes/*", "accessors"},
    {"meshes", "primitives/*/indices", "accessors"},
    {"meshes", "primitives/*/material", "materials"},
    {"meshes", "primitives/*/targets/*/*", "accessors"},
    {"accessors", "bufferView", "bufferViews"},
    {"accessors", "sparse/indices/bufferView", "bufferViews"},
    {"accessors", "sparse/values/bufferView", "bufferViews"},
    {"bufferViews", "buffer", "buffers"},
    {"images", "bufferView", "bufferViews"},
    {"textures", "source", "images"},
    {"textures", "sampler", "samplers"},
    {"materials", "pbrMetallicRoughness/baseColorTexture/index", "textures"},
    {"materials", "pbrMetallicRoughness/metallicRoughnessTexture/index", "textures"},
    {"materials", "normalTexture/index", "textures"},
    {"materials", "occlusionTexture/index", "textures"},
    {"materials", "emissiveTexture/index", "textures"},
    {"materials", "extensions/KHR_materials_specular/specularTexture/index", "textures"},
    {"materials", "extensions/KHR_materials_specular/specularColorTexture/index", "textures"},
    {"materials", "extensions/KHR_materials_transmission/transmissionTexture/index", "textures"},
    {"materials", "extensions/KHR_materials_volume/thicknessTexture/index", "textures"},
    {"animations", "channels/*/sampler", "@samplers"},
    {"animations", "channels/*/target/node", "nodes"},
    {"animations", "samplers/*/input", "accessors"},
    {"animations", "samplers/*/output", "accessors"},
    {"skins", "joints/*", "nodes"},
    {"skins", "inverseBindMatrices", "accessors"},
};

constexpr const char* kCollections[] = {"scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers", "images",
                                        "textures", "samplers", "materials", "cameras", "animations", "skins"};

struct Checker {
    const Json& doc;
    const std::string& file;

    const Json* resolve(const Json& from, std::string_view path) const
    {
        const Json* at = &from;
        std::size_t start = 0;
        while (start <= path.size() && at) {
            const std::size_t slash = path.find('/', start);
            const std::string key(path.substr(start, slash - start));
            at = at->is_object() && at->contains(key) ? &(*at)[key] : nullptr;
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        return at;
    }

    void requireArrayOfObjects(const Json* array, const std::string& where) const
    {
        if (!array) return;
        if (!array->is_array()) throw FileError(file, "wrong-type", where + " must be an array");
        for (std::size_t i = 0; i < array->size(); ++i)
            if (!(*array)[i].is_object()) throw FileError(file, "wrong-type", where + "[" + std::to_string(i) + "] must be an object");
    }

    void checkIndex(const Json& value, const std::string& where, const Json* target, const std::string& targetName) const
    {
        if (!value.is_number_unsigned()) throw FileError(file, "wrong-type", where + " must be an index (a non-negative integer)");
        const std::size_t size = target && target->is_array() ? target->size() : 0;
        if (value.get<std::uint64_t>() >= size)
            throw FileError(file, "dangling-index", where + " is " + std::to_string(value.get<std::uint64_t>()) + ", but the file has " +
                                                        std::to_string(size) + " " + targetName);
    }

    // Walks the rest of the path; "*" fans out over arrays and objects.
    void walk(const Json& at, std::string_view path, const std::string& where, const Json* target, const std::string& targetName) const
    {
        if (path.empty()) return checkIndex(at, where, target, targetName);
        const std::size_t slash = path.find('/');
        const std::string key(path.substr(0, slash));
        const std::string_view rest = slash == std::string_view::npos ? std::string_view{} : path.substr(slash + 1);
        if (key == "*") {
            if (at.is_array()) {
                for (std::size_t i = 0; i < at.size(); ++i) walk(at[i], rest, where + "[" + std::to_string(i) + "]", target, targetName);
            } else if (at.is_object()) {
                for (const auto& [name, value] : at.items()) walk(value, rest, where + "." + name, target, targetName);
            } else {
                throw FileError(file, "wrong-type", where + " must be an array or an object");
            }
            return;
        }
        if (!at.is_object()) throw FileError(file, "wrong-type", where + " must be an object");
        if (auto it = at.find(key); it != at.end()) walk(*it, rest, where + "." + key, target, targetName);
    }

    void check(const Reference& ref) const
    {
        const Json* items = resolve(doc, ref.collection);
        if (!items) return;
        for (std::size_t i = 0; i < items->size(); ++i) {
            const Json& item = (*items)[i];
            const bool local = ref.target[0] == '@';
            const Json* target = local ? resolve(item, ref.target + 1) : resolve(doc, ref.target);
            const std::string targetName = local ? std::string(ref.target + 1) + " in this animation" : ref.target;
            walk(item, ref.path, std::string(ref.collection) + "[" + std::to_string(i) + "]", target, targetName);
        }
    }
};

} // namespace

void validateGltfReferences(const nlohmann::json& doc, const std::string& file)
{
    const Checker checker{doc, file};
    for (const char* collection : kCollections) checker.requireArrayOfObjects(checker.resolve(doc, collection), collection);
    checker.requireArrayOfObjects(checker.resolve(doc, "extensions/KHR_lights_punctual/lights"), "extensions.KHR_lights_punctual.lights");
    if (const Json* scene = checker.resolve(doc, "scene")) checker.checkIndex(*scene, "scene", checker.resolve(doc, "scenes"), "scenes");
    for (const Reference& ref : kReferences) checker.check(ref);
}

} // namespace glint
