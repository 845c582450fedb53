// loadGltfFromMemory: the steps of gltf_reader.h in order.
#include "gltf_reader.h"

#include "gltf_read_json.h"
#include "scene/io/files/confined_fs.h"

namespace glint {

namespace {

// The asset's own fields (copyright, extras, ...) and top-level extensions/extras Glint does not
// interpret; version and generator are written fresh on save.
nlohmann::json documentUnknown(const nlohmann::json& doc)
{
    nlohmann::json unknown = unknownMembers(doc, {"KHR_lights_punctual"});
    if (auto asset = doc.find("asset"); asset != doc.end() && asset->is_object()) {
        nlohmann::json kept = *asset;
        kept.erase("version");
        kept.erase("generator");
        if (!kept.empty()) unknown["asset"] = std::move(kept);
    }
    return unknown;
}

void noteUnsupportedTopLevel(GltfReadContext& ctx)
{
    if (ctx.doc.contains("skins") && !ctx.doc["skins"].empty())
        ctx.scene.unsupported.push_back({ctx.file, "skins-dropped", std::to_string(ctx.doc["skins"].size()) + " skins are not kept"});
}

} // namespace

LoadResult loadGltfFromMemory(std::span<const std::uint8_t> bytes, const std::filesystem::path& baseDir, const std::string& displayName,
                              const LoadOptions& options)
{
    const GltfSource source = splitGltfContainer(bytes, displayName);
    const nlohmann::json doc = parseGltfJson(source.json, displayName, options.maxJsonDepth);
    validateGltfReferences(doc, displayName);
    ConfinedFolder folder{baseDir};
    validateGltfData(doc, source, folder, displayName, options);
    const tinygltf::Model model = loadWithTinygltf(bytes, source, folder, displayName);

    GltfReadContext ctx{displayName, options, doc, model, {}, {}, {}, {}, {}, {}, {}, {}};
    readImagesAndTextures(ctx);
    readMaterials(ctx);
    readMeshes(ctx);
    readNodes(ctx);
    readAnimations(ctx);
    noteUnsupportedTopLevel(ctx);
    noteDroppedMembers(ctx);
    ctx.scene.unknown = documentUnknown(doc);
    return {std::move(ctx.scene), std::move(ctx.warnings)};
}

} // namespace glint
