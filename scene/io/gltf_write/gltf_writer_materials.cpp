// Materials (metallic-roughness plus the KHR_materials_* extensions Glint renders), textures and
// samplers. An extension is written only when it differs from its defaults, which are Material{}'s.
#include "gltf_writer_context.h"
#include "scene/io/json/json_numbers.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace glint {

namespace {

template <class Vec>
nlohmann::json vecJson(const Vec& v) { return jsonFloats({glm::value_ptr(v), Vec::length()}); }

nlohmann::json textureTransformJson(const TextureTransform& t)
{
    nlohmann::json out{{"offset", vecJson(t.offset)}, {"rotation", jsonFloat(t.rotation)}, {"scale", vecJson(t.scale)}};
    if (t.texCoord >= 0) out["texCoord"] = t.texCoord;
    return out;
}

// `scaleKey`: "scale" (normal), "strength" (occlusion), or null for plain textureInfo.
void writeTextureRef(GltfWriteContext& ctx, nlohmann::json& parent, const char* key, const TextureRef& ref,
                     const char* scaleKey = nullptr)
{
    if (!ref.valid()) return;
    auto it = ctx.textures.find(ref.texture);
    if (it == ctx.textures.end()) {
        ctx.drop("dangling-texture", std::string("a material's ") + key + " refers to texture " +
                                         std::to_string(ref.texture.value) + ", which does not exist");
        return;
    }
    nlohmann::json info{{"index", it->second}};
    if (ref.texCoord != 0) info["texCoord"] = ref.texCoord;
    if (scaleKey && ref.scale != 1.0f) info[scaleKey] = jsonFloat(ref.scale);
    if (!ref.transform.isIdentity()) info["extensions"]["KHR_texture_transform"] = textureTransformJson(ref.transform);
    mergeUnknown(info, ref.unknown);
    parent[key] = std::move(info);
}

void writeMetallicRoughness(GltfWriteContext& ctx, nlohmann::json& out, const Material& m)
{
    nlohmann::json pbr = nlohmann::json::object();
    if (m.baseColorFactor != glm::vec4(1.0f)) pbr["baseColorFactor"] = vecJson(m.baseColorFactor);
    writeTextureRef(ctx, pbr, "baseColorTexture", m.baseColorTexture);
    if (m.metallicFactor != 1.0f) pbr["metallicFactor"] = jsonFloat(m.metallicFactor);
    if (m.roughnessFactor != 1.0f) pbr["roughnessFactor"] = jsonFloat(m.roughnessFactor);
    writeTextureRef(ctx, pbr, "metallicRoughnessTexture", m.metallicRoughnessTexture);
    out["pbrMetallicRoughness"] = std::move(pbr);
}

void writeEmission(GltfWriteContext& ctx, nlohmann::json& out, const Material& m)
{
    if (m.emissiveFactor != glm::vec3(0.0f)) out["emissiveFactor"] = vecJson(m.emissiveFactor);
    writeTextureRef(ctx, out, "emissiveTexture", m.emissiveTexture);
    if (m.emissiveStrength != 1.0f)
        out["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", jsonFloat(m.emissiveStrength)}};
}

void writeSpecular(GltfWriteContext& ctx, nlohmann::json& out, const Material& m)
{
    nlohmann::json ext = nlohmann::json::object();
    if (m.specularFactor != 1.0f) ext["specularFactor"] = jsonFloat(m.specularFactor);
    writeTextureRef(ctx, ext, "specularTexture", m.specularTexture);
    if (m.specularColorFactor != glm::vec3(1.0f)) ext["specularColorFactor"] = vecJson(m.specularColorFactor);
    writeTextureRef(ctx, ext, "specularColorTexture", m.specularColorTexture);
    if (!ext.empty()) out["extensions"]["KHR_materials_specular"] = std::move(ext);
}

void writeTransmissionAndVolume(GltfWriteContext& ctx, nlohmann::json& out, const Material& m)
{
    nlohmann::json transmission = nlohmann::json::object();
    if (m.transmissionFactor != 0.0f) transmission["transmissionFactor"] = jsonFloat(m.transmissionFactor);
    writeTextureRef(ctx, transmission, "transmissionTexture", m.transmissionTexture);
    if (!transmission.empty()) out["extensions"]["KHR_materials_transmission"] = std::move(transmission);

    if (m.ior != 1.5f) out["extensions"]["KHR_materials_ior"] = {{"ior", jsonFloat(m.ior)}};

    nlohmann::json volume = nlohmann::json::object();
    if (m.thicknessFactor != 0.0f) volume["thicknessFactor"] = jsonFloat(m.thicknessFactor);
    writeTextureRef(ctx, volume, "thicknessTexture", m.thicknessTexture);
    if (std::isfinite(m.attenuationDistance)) volume["attenuationDistance"] = jsonFloat(m.attenuationDistance);
    if (m.attenuationColor != glm::vec3(1.0f)) volume["attenuationColor"] = vecJson(m.attenuationColor);
    if (!volume.empty()) out["extensions"]["KHR_materials_volume"] = std::move(volume);
}

// Glint's own extension; extensionsUsed lists it (it is collected from what is written), never
// extensionsRequired: other tools render the volume as absorption only.
void writeVolumeScatter(nlohmann::json& out, const Material& m)
{
    nlohmann::json scatter = nlohmann::json::object();
    if (m.scatterColor != glm::vec3(0.0f)) scatter["scatterColor"] = vecJson(m.scatterColor);
    if (m.scatterAnisotropy != 0.0f) scatter["scatterAnisotropy"] = jsonFloat(m.scatterAnisotropy);
    if (!scatter.empty()) out["extensions"]["GLINT_materials_volume_scatter"] = std::move(scatter);
}

void writeAlpha(nlohmann::json& out, const Material& m)
{
    if (m.alphaMode == AlphaMode::Mask) out["alphaMode"] = "MASK";
    if (m.alphaMode == AlphaMode::Blend) out["alphaMode"] = "BLEND";
    if (m.alphaCutoff != 0.5f) out["alphaCutoff"] = jsonFloat(m.alphaCutoff);
    if (m.doubleSided) out["doubleSided"] = true;
}

nlohmann::json materialJson(GltfWriteContext& ctx, const Material& m)
{
    nlohmann::json out = nlohmann::json::object();
    if (!m.name.empty()) out["name"] = m.name;
    writeMetallicRoughness(ctx, out, m);
    writeTextureRef(ctx, out, "normalTexture", m.normalTexture, "scale");
    writeTextureRef(ctx, out, "occlusionTexture", m.occlusionTexture, "strength");
    writeEmission(ctx, out, m);
    writeSpecular(ctx, out, m);
    writeTransmissionAndVolume(ctx, out, m);
    writeVolumeScatter(out, m);
    writeAlpha(out, m);
    mergeUnknown(out, m.unknown);
    return out;
}

nlohmann::json textureJson(GltfWriteContext& ctx, TextureId id, const Texture& t)
{
    nlohmann::json out = nlohmann::json::object();
    if (!t.name.empty()) out["name"] = t.name;
    if (auto it = ctx.images.find(t.image); it != ctx.images.end())
        out["source"] = it->second;
    else if (t.image.valid())
        ctx.drop("dangling-image", "texture " + std::to_string(id.value) + " refers to a missing image");
    if (auto it = ctx.samplers.find(t.sampler); it != ctx.samplers.end()) out["sampler"] = it->second;
    mergeUnknown(out, t.unknown);
    return out;
}

nlohmann::json samplerJson(const Sampler& s)
{
    nlohmann::json out{{"wrapS", static_cast<int>(s.wrapS)}, {"wrapT", static_cast<int>(s.wrapT)}};
    if (!s.name.empty()) out["name"] = s.name;
    if (s.magFilter != Filter::Unset) out["magFilter"] = static_cast<int>(s.magFilter);
    if (s.minFilter != Filter::Unset) out["minFilter"] = static_cast<int>(s.minFilter);
    mergeUnknown(out, s.unknown);
    return out;
}

} // namespace

void writeMaterials(GltfWriteContext& ctx)
{
    for (const auto& [id, material] : ctx.scene.materials) ctx.root["materials"].push_back(materialJson(ctx, material));
    for (nlohmann::json& material : ctx.generatedMaterials) ctx.root["materials"].push_back(std::move(material));
    for (const auto& [id, texture] : ctx.scene.textures) ctx.root["textures"].push_back(textureJson(ctx, id, texture));
    for (const auto& [id, sampler] : ctx.scene.samplers) ctx.root["samplers"].push_back(samplerJson(sampler));
}

} // namespace glint
