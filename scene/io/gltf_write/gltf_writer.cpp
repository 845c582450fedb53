// The glTF writer's top level: index maps, the parts in a fixed order, asset, extensionsUsed and
// the buffer. Nothing here depends on the clock, addresses or hash-map order, so the same Scene
// always gives the same JSON text and buffer bytes.
#include "gltf_writer.h"

#include "gltf_writer_context.h"
#include "scene/io/json/json_numbers.h"

#include <array>
#include <bit>
#include <cstdio>
#include <set>

#ifndef GLINT_VERSION_STRING
#error "GLINT_VERSION_STRING (the CMake project version) must be defined"
#endif

namespace glint {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian; so is every target Glint supports");

std::string glintGenerator() { return std::string("Glint ") + GLINT_VERSION_STRING; }

namespace {

template <class IdT, class T>
IndexOf<IdT> indicesInIdOrder(const AssetTable<IdT, T>& table)
{
    IndexOf<IdT> indices;
    for (const auto& entry : table) indices.emplace(entry.first, static_cast<int>(indices.size()));
    return indices;
}

void buildIndexMaps(GltfWriteContext& ctx)
{
    for (const auto& entry : ctx.scene.nodes()) ctx.nodes.emplace(entry.first, static_cast<int>(ctx.nodes.size()));
    ctx.meshes = indicesInIdOrder(ctx.scene.meshes);
    ctx.materials = indicesInIdOrder(ctx.scene.materials);
    ctx.textures = indicesInIdOrder(ctx.scene.textures);
    ctx.images = indicesInIdOrder(ctx.scene.images);
    ctx.samplers = indicesInIdOrder(ctx.scene.samplers);
}

// Every name under an "extensions" object anywhere in the document (extras are opaque data).
void collectExtensionNames(const nlohmann::json& value, std::set<std::string>& names)
{
    if (value.is_array()) {
        for (const auto& element : value) collectExtensionNames(element, names);
        return;
    }
    if (!value.is_object()) return;
    for (const auto& [key, member] : value.items()) {
        if (key == "extras") continue;
        if (key == "extensions" && member.is_object())
            for (const auto& [name, content] : member.items()) names.insert(name);
        collectExtensionNames(member, names);
    }
}

// Scene::unknown holds the asset's other fields and top-level extensions/extras; the lists of used
// and required extensions are recomputed from what is actually written.
void writeAssetAndUnknown(GltfWriteContext& ctx)
{
    ctx.root["asset"] = {{"version", "2.0"}, {"generator", glintGenerator()}};
    nlohmann::json unknown = ctx.scene.unknown;
    if (unknown.is_object()) {
        unknown.erase("extensionsUsed");
        unknown.erase("extensionsRequired");
    }
    mergeUnknown(ctx.root, unknown);
    std::set<std::string> used;
    collectExtensionNames(ctx.root, used);
    if (!used.empty()) ctx.root["extensionsUsed"] = used;
}

void reportUnsupported(GltfWriteContext& ctx)
{
    for (const Warning& w : ctx.scene.unsupported) ctx.dropped.push_back({ctx.options.displayName, w.code, w.message});
}

// FNV-1a: a content name for the .bin, so an interrupted save never pairs an old .gltf with a new .bin.
std::string contentHash(const std::vector<std::uint8_t>& bytes)
{
    std::uint64_t hash = 14695981039346656037ull;
    for (std::uint8_t b : bytes) hash = (hash ^ b) * 1099511628211ull;
    std::array<char, 17> text{};
    std::snprintf(text.data(), text.size(), "%016llx", static_cast<unsigned long long>(hash));
    return text.data();
}

void writeBuffer(GltfWriteContext& ctx, GltfOutput& out)
{
    out.bin = ctx.buffers.bytes();
    if (!ctx.buffers.accessors().empty()) ctx.root["accessors"] = std::move(ctx.buffers.accessors());
    if (!ctx.buffers.bufferViews().empty()) ctx.root["bufferViews"] = std::move(ctx.buffers.bufferViews());
    if (out.bin.empty()) return;
    nlohmann::json buffer{{"byteLength", out.bin.size()}};
    if (ctx.options.container == GltfContainer::Text) {
        out.binUri = ctx.options.baseName + "." + contentHash(out.bin) + ".bin";
        buffer["uri"] = out.binUri;
    }
    ctx.root["buffers"] = nlohmann::json::array({std::move(buffer)});
}

} // namespace

GltfOutput writeGltf(const Scene& scene, const GltfWriteOptions& options)
{
    GltfWriteContext ctx{scene, options};
    buildIndexMaps(ctx);
    reportUnsupported(ctx);
    writeMeshes(ctx);
    writeNodes(ctx);
    writeAnimations(ctx);
    writeMaterials(ctx);
    writeImages(ctx);

    GltfOutput out;
    writeBuffer(ctx, out);
    writeAssetAndUnknown(ctx);
    const bool text = options.container == GltfContainer::Text;
    out.json = deterministicJsonText(ctx.root, text ? 1 : -1) + (text ? "\n" : "");
    out.images = std::move(ctx.externalImages);
    out.dropped = std::move(ctx.dropped);
    return out;
}

} // namespace glint
