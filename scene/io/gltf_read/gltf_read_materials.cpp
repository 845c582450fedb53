// glTF metallic-roughness materials plus the KHR_materials_* extensions Glint renders, its own
// GLINT_materials_volume_scatter, and KHR_texture_transform on every texture reference.
#include "gltf_read_json.h"
#include "gltf_reader.h"

#include <algorithm>
#include <limits>

namespace glint {

namespace {

// The bound of GLINT_materials_volume_scatter's Henyey-Greenstein g, as the project's fog's.
constexpr float kMaxScatterAnisotropy = 0.99f;

TextureTransform readTextureTransform(const JsonReader& json, const Json& ext, const std::string& where)
{
    TextureTransform t;
    t.offset = json.vec2(ext, "offset", t.offset, where);
    t.rotation = json.number(ext, "rotation", t.rotation, where);
    t.scale = json.vec2(ext, "scale", t.scale, where);
    t.texCoord = json.index(ext, "texCoord", where);
    return t;
}

// A textureInfo; `scaleKey` is "scale" (normal) or "strength" (occlusion).
TextureRef readTextureRef(const GltfReadContext& ctx, const Json& parent, const char* key, const std::string& where, const char* scaleKey = nullptr)
{
    const JsonReader json{ctx.file};
    TextureRef ref;
    const Json* info = json.member(parent, key);
    if (!info) return ref;
    const std::string at = where + "." + key;
    if (!info->is_object()) json.wrongType(where, key, "an object");
    const int index = json.index(*info, "index", at);
    if (index < 0) ctx.fail("wrong-type", at + ".index is missing");
    ref.texture = ctx.textureIds.at(static_cast<std::size_t>(index));
    ref.texCoord = std::max(0, json.index(*info, "texCoord", at));
    if (scaleKey) ref.scale = json.number(*info, scaleKey, 1.0f, at);
    if (const Json* transform = json.extension(*info, "KHR_texture_transform", at))
        ref.transform = readTextureTransform(json, *transform, at + ".extensions.KHR_texture_transform");
    ref.unknown = unknownMembers(*info, {"KHR_texture_transform"});
    return ref;
}

AlphaMode alphaModeFrom(const GltfReadContext& ctx, const std::string& mode, const std::string& where)
{
    if (mode.empty() || mode == "OPAQUE") return AlphaMode::Opaque;
    if (mode == "MASK") return AlphaMode::Mask;
    if (mode == "BLEND") return AlphaMode::Blend;
    ctx.fail("wrong-type", where + ".alphaMode is \"" + mode + "\" (OPAQUE, MASK or BLEND)");
}

void readPbr(const GltfReadContext& ctx, const Json& source, const std::string& where, Material& m)
{
    const JsonReader json{ctx.file};
    const Json* pbr = json.member(source, "pbrMetallicRoughness");
    if (!pbr) return;
    if (!pbr->is_object()) json.wrongType(where, "pbrMetallicRoughness", "an object");
    const std::string at = where + ".pbrMetallicRoughness";
    m.baseColorFactor = json.vec4(*pbr, "baseColorFactor", m.baseColorFactor, at);
    m.baseColorTexture = readTextureRef(ctx, *pbr, "baseColorTexture", at);
    m.metallicFactor = json.number(*pbr, "metallicFactor", m.metallicFactor, at);
    m.roughnessFactor = json.number(*pbr, "roughnessFactor", m.roughnessFactor, at);
    m.metallicRoughnessTexture = readTextureRef(ctx, *pbr, "metallicRoughnessTexture", at);
}

void readExtensions(const GltfReadContext& ctx, const Json& source, const std::string& where, Material& m)
{
    const JsonReader json{ctx.file};
    const std::string at = where + ".extensions.";
    if (const Json* e = json.extension(source, "KHR_materials_emissive_strength", where))
        m.emissiveStrength = json.number(*e, "emissiveStrength", m.emissiveStrength, at + "KHR_materials_emissive_strength");
    if (const Json* e = json.extension(source, "KHR_materials_specular", where)) {
        const std::string w = at + "KHR_materials_specular";
        m.specularFactor = json.number(*e, "specularFactor", m.specularFactor, w);
        m.specularTexture = readTextureRef(ctx, *e, "specularTexture", w);
        m.specularColorFactor = json.vec3(*e, "specularColorFactor", m.specularColorFactor, w);
        m.specularColorTexture = readTextureRef(ctx, *e, "specularColorTexture", w);
    }
    if (const Json* e = json.extension(source, "KHR_materials_transmission", where)) {
        m.transmissionFactor = json.number(*e, "transmissionFactor", m.transmissionFactor, at + "KHR_materials_transmission");
        m.transmissionTexture = readTextureRef(ctx, *e, "transmissionTexture", at + "KHR_materials_transmission");
    }
    if (const Json* e = json.extension(source, "KHR_materials_ior", where)) m.ior = json.number(*e, "ior", m.ior, at + "KHR_materials_ior");
    if (const Json* e = json.extension(source, "KHR_materials_volume", where)) {
        const std::string w = at + "KHR_materials_volume";
        m.thicknessFactor = json.number(*e, "thicknessFactor", m.thicknessFactor, w);
        m.thicknessTexture = readTextureRef(ctx, *e, "thicknessTexture", w);
        if (json.member(*e, "attenuationDistance")) m.attenuationDistance = json.number(*e, "attenuationDistance", 0.0f, w);
        m.attenuationColor = json.vec3(*e, "attenuationColor", m.attenuationColor, w);
    }
    // Glint's own: the share of KHR_materials_volume's attenuation that scatters (docs/FILE_FORMAT.md).
    if (const Json* e = json.extension(source, "GLINT_materials_volume_scatter", where)) {
        const std::string w = at + "GLINT_materials_volume_scatter";
        m.scatterColor = json.vec3(*e, "scatterColor", m.scatterColor, w);
        m.scatterAnisotropy = json.number(*e, "scatterAnisotropy", m.scatterAnisotropy, w);
    }
}

// glTF bounds these factors; renderers disagree on what a value beyond them means (a roughness of
// -5 is no surface at all). Lenient but loud: clamped into range, each one named.
void clampFactor(GltfReadContext& ctx, float& value, float low, float high, const std::string& where)
{
    if (value >= low && value <= high) return;
    const float clamped = std::clamp(value, low, high);
    ctx.warn("invalid-value", where + " is " + floatText(value) + ", outside " + floatText(low) +
                                  (high == std::numeric_limits<float>::max() ? " or more" : ".." + floatText(high)) +
                                  ": clamped to " + floatText(clamped));
    value = clamped;
}

void clampFactors(GltfReadContext& ctx, Material& m, const std::string& where)
{
    constexpr float kUnbounded = std::numeric_limits<float>::max();
    const std::string pbr = where + ".pbrMetallicRoughness.";
    for (int i = 0; i < 4; ++i)
        clampFactor(ctx, m.baseColorFactor[i], 0.0f, 1.0f, pbr + "baseColorFactor[" + std::to_string(i) + "]");
    clampFactor(ctx, m.metallicFactor, 0.0f, 1.0f, pbr + "metallicFactor");
    clampFactor(ctx, m.roughnessFactor, 0.0f, 1.0f, pbr + "roughnessFactor");
    // Above 1 is kept: files written before KHR_materials_emissive_strength encode strength there.
    for (int i = 0; i < 3; ++i)
        clampFactor(ctx, m.emissiveFactor[i], 0.0f, kUnbounded, where + ".emissiveFactor[" + std::to_string(i) + "]");
    clampFactor(ctx, m.alphaCutoff, 0.0f, kUnbounded, where + ".alphaCutoff");
    const std::string ext = where + ".extensions.";
    clampFactor(ctx, m.emissiveStrength, 0.0f, kUnbounded, ext + "KHR_materials_emissive_strength.emissiveStrength");
    clampFactor(ctx, m.specularFactor, 0.0f, 1.0f, ext + "KHR_materials_specular.specularFactor");
    clampFactor(ctx, m.transmissionFactor, 0.0f, 1.0f, ext + "KHR_materials_transmission.transmissionFactor");
    clampFactor(ctx, m.thicknessFactor, 0.0f, kUnbounded, ext + "KHR_materials_volume.thicknessFactor");
    // A scattered share above 1 would add light; |g| = 1 is a delta lobe the sampling cannot take.
    const std::string scatter = ext + "GLINT_materials_volume_scatter.";
    for (int i = 0; i < 3; ++i)
        clampFactor(ctx, m.scatterColor[i], 0.0f, 1.0f, scatter + "scatterColor[" + std::to_string(i) + "]");
    clampFactor(ctx, m.scatterAnisotropy, -kMaxScatterAnisotropy, kMaxScatterAnisotropy, scatter + "scatterAnisotropy");
}

Material readMaterial(GltfReadContext& ctx, std::size_t index)
{
    const JsonReader json{ctx.file};
    const Json& source = ctx.doc["materials"][index];
    const std::string where = "materials[" + std::to_string(index) + "]";
    Material m;
    m.name = json.string(source, "name", where);
    readPbr(ctx, source, where, m);
    m.normalTexture = readTextureRef(ctx, source, "normalTexture", where, "scale");
    m.occlusionTexture = readTextureRef(ctx, source, "occlusionTexture", where, "strength");
    m.emissiveTexture = readTextureRef(ctx, source, "emissiveTexture", where);
    m.emissiveFactor = json.vec3(source, "emissiveFactor", m.emissiveFactor, where);
    m.alphaMode = alphaModeFrom(ctx, json.string(source, "alphaMode", where), where);
    m.alphaCutoff = json.number(source, "alphaCutoff", m.alphaCutoff, where);
    m.doubleSided = json.boolean(source, "doubleSided", m.doubleSided, where);
    readExtensions(ctx, source, where, m);
    clampFactors(ctx, m, where);
    m.unknown = unknownMembers(source, {"KHR_materials_emissive_strength", "KHR_materials_specular", "KHR_materials_transmission",
                                        "KHR_materials_ior", "KHR_materials_volume", "GLINT_materials_volume_scatter"});
    return m;
}

} // namespace

// The emissive material of an area light's fallback mesh: Glint drops it with the mesh and writes it
// again from the light (GLINT_area_light).
bool isAreaLightMaterial(const nlohmann::json& material)
{
    return material.is_object() && material.contains("extensions") && material["extensions"].is_object() &&
           material["extensions"].contains("GLINT_area_light_material");
}

void readMaterials(GltfReadContext& ctx)
{
    const std::size_t count = ctx.doc.contains("materials") ? ctx.doc["materials"].size() : 0;
    for (std::size_t i = 0; i < count; ++i)
        ctx.materialIds.push_back(isAreaLightMaterial(ctx.doc["materials"][i]) ? MaterialId{}
                                                                                  : ctx.scene.materials.add(readMaterial(ctx, i)));
}

} // namespace glint
